// `shaderport fix` of a ShaderToy JSON document: every pass (and Common) fixed as
// the site compiles it, the fixed code written back into the code strings only.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "driver/port/port_file.h"
#include "driver/read_input.h"

namespace shaderport::driver::project {

struct FixedDocument {
  const SourceFile* document = nullptr;  // the JSON as read
  std::string text;                      // the JSON with fixed code strings
  std::vector<PortResult> passes;        // one per pass: findings and fixes
  bool read_failed = false;              // unreadable or not a project: `text` is empty
  DiagnosticList problems;               // why (input/*), on `document`

  bool Changed() const { return !read_failed && document != nullptr && text != document->Text(); }
};

FixedDocument FixDocument(const std::filesystem::path& path, InputText input,
                          const PortOptions& options, SourceManager& sources);

}  // namespace shaderport::driver::project
