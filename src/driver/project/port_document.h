// `shaderport port` of a ShaderToy JSON document: each project ported pass by pass
// (port_project.h), and the files that result: one WebGL2 shader per drawn pass, or
// one page per project (--emit html).
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "driver/project/json_project_reader.h"
#include "driver/project/port_project.h"
#include "driver/read_input.h"

namespace shaderport::driver::project {

struct PortedDocument {
  const SourceFile* document = nullptr;
  bool read_failed = false;  // unreadable or not a project: `problems` says why
  DiagnosticList problems;
  std::unique_ptr<ProjectDocument> read;  // the projects `ported` points into
  std::vector<PortedProject> ported;      // one per project (when ported)

  // Every finding once, for the text report (the document's problems included).
  PortResult Findings() const;
  // Read, and every pass of every project ported to a shader that compiles.
  bool Validated() const;
};

// With `port` false the projects are only read (for FolderOutputs).
PortedDocument PortDocument(const std::filesystem::path& path, InputText input,
                            const PortOptions& options, SourceManager& sources, bool port = true);

// A ShaderToy pass on its own (a .glsl file), ported as a project with one Image
// tab; findings stay on the file.
PortedDocument PortSinglePass(const std::filesystem::path& path, InputText input,
                              const PortOptions& options, SourceManager& sources);

// A project folder (a directory with shadertoy.toml).
PortedDocument PortFolder(const std::filesystem::path& directory, const PortOptions& options,
                          SourceManager& sources);

struct DocumentOutput {
  // Below the output base: "image.frag", "buffer-a.frag", or with several projects
  // "<id>/image.frag"; for pages "" (one project) or "<id>.html".
  std::filesystem::path relative;
  std::string text;
};

// The ported shaders of every drawn pass (Common is inlined; a Sound pass is
// written too, for a page of the user's own).
std::vector<DocumentOutput> ShaderOutputs(const PortedDocument& document);
// One page per project.
std::vector<DocumentOutput> PageOutputs(const PortedDocument& document);
// The folder layout of every project (the code as written, and shadertoy.toml).
std::vector<DocumentOutput> FolderOutputs(const PortedDocument& document);

// A page for shaders of the user's own harness (WebGL1, WebGL2, a harness dialect
// such as raymarch-blog), ported: a fragment shader alone (the full-screen triangle,
// with render's feeder vertex shader for its inputs), a vertex shader alone (on
// render's sphere, with render's depth-shading fragment shader) or a vertex and
// fragment pair (on the sphere). Either may be null, not both.
DocumentOutput ProgramPage(const PortResult* vertex, const PortResult* fragment);

}  // namespace shaderport::driver::project
