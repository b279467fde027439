// One self-contained WebGL2 page per ShaderToy project: the ported passes run as the
// site runs them (Buffers A-D, Cube A, Image), with the site's uniforms, keyboard,
// mouse, pause and restart, and a compile-error panel on the user's lines. Nothing
// is loaded from anywhere: the runtime and the shaders are inline. See
// docs/html-pages.md for the page's behaviour and its test hooks.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "driver/dialect.h"

namespace shaderport::driver::project {

// What a channel reads; procedural stand-ins replace the site's media files.
enum class PageInputKind {
  kNone,        // unbound: samples (0,0,0,1), iChannelResolution 0
  kBuffer,      // Buffer A-D (`buffer` = 0..3)
  kCubeBuffer,  // the Cube A pass's cube map
  kTexture,     // procedural 2D 256x256 (render's), overridable by a file
  kCubemap,     // procedural cube, 64x64 faces
  kVolume,      // procedural 3D 32x32x32
  kKeyboard,    // 256x3 R8 key state
  kVideo,       // procedural 2D, as render draws it
  kAudio,       // procedural 2D, as render draws it
};

struct PageInput {
  int channel = 0;  // 0..3
  PageInputKind kind = PageInputKind::kNone;
  int buffer = -1;                // kBuffer: 0..3
  std::string filter = "mipmap";  // nearest | linear | mipmap
  std::string wrap = "repeat";    // clamp | repeat
  bool vflip = true;              // applies to user-given images only
};

// Lines [ported_first, ported_first + count) of a pass's shader came from the
// user's text `origin` (a tab name: "Common", "Buffer A"), starting at user_first.
// Lines outside every run were generated (header, main()).
struct PageLineRun {
  uint32_t ported_first = 1;  // 1-based
  uint32_t count = 0;
  std::string origin;
  uint32_t user_first = 1;  // 1-based
};

struct PagePass {
  std::string tab_name;  // "Image", "Buffer A", "Cube A", "Sound"
  model::PassKind kind = model::PassKind::kImage;
  int output_buffer = -1;  // Buffer passes: 0..3
  std::vector<PageInput> inputs;
  // The complete WebGL2 fragment shader (#version 300 es, uniforms, main()); empty
  // when the port failed, and then `port_errors` says why.
  std::string fragment_shader;
  std::vector<PageLineRun> lines;
  std::string port_errors;  // shown in the error panel as text
  // A program of the user's own (not a ShaderToy tab), drawn as `shaderport render`
  // draws it: this vertex shader (empty: the full-screen triangle), on render's
  // sphere mesh with a depth test when `mesh`; uniforms other than ShaderToy's get
  // render's defaults by name and type (docs/html-pages.md).
  std::string vertex_shader;
  std::vector<PageLineRun> vertex_lines;  // as `lines`, for vertex_shader
  bool mesh = false;
};

struct PageProject {
  std::string name;
  std::string id;
  std::string author;
  // Any order. A Common pass is ignored (the port inlines Common); Sound plays on
  // request (browsers start audio only after a click).
  std::vector<PagePass> passes;
};

struct PageOptions {
  uint32_t cube_size = 256;  // Cube A faces (the site draws 1024x1024)
};

// The page as one HTML document. Every string of the project is embedded as JSON
// text with `<`, `>`, `&`, U+2028 and U+2029 escaped, so no name or code can end
// the script element or be parsed as markup.
std::string BuildProjectPage(const PageProject& project, const PageOptions& options = {});

struct PortedProject;  // driver/project/port_project.h

// The page of a ported project: each pass's ported text and line origins, its tab,
// output and inputs. A pass the port left without text gets its error findings as
// `port_errors`.
PageProject PageFromPorted(const PortedProject& ported);

// Runs from one origin per ported line (index 0: line 1): consecutive lines of one
// origin with consecutive user lines form a run; an empty origin is generated text.
struct LineOrigin {
  std::string origin;  // tab name, or empty
  uint32_t line = 0;   // 1-based in that tab
};
std::vector<PageLineRun> LineRunsFromOrigins(const std::vector<LineOrigin>& lines);

// The JSON the page embeds (exposed for tests).
std::string PageProjectJson(const PageProject& project, const PageOptions& options = {});

// Line runs for a ported text composed as header | Common | pass code | epilogue:
// `header_lines` generated lines, then `common_lines` lines of Common (0: none),
// then the pass's own lines.
std::vector<PageLineRun> ComposedLineRuns(uint32_t header_lines, uint32_t common_lines,
                                          uint32_t pass_lines, const std::string& pass_tab);

// The page's runtime files (src/driver/project/page/), compiled in by
// cmake/embed_text_files.cmake so that an installed binary reads no data files.
namespace page_files {
struct EmbeddedTextFile {
  std::string_view name;  // "runtime.js", "textures.js", "sound.js", "page.css"
  std::string_view text;
};
std::span<const EmbeddedTextFile> EmbeddedPageFiles();
}  // namespace page_files

}  // namespace shaderport::driver::project
