// A ShaderToy project: the tabs of one shader on the site (Common, Buffers A-D,
// Cube A, Sound, Image) with their channel bindings, whatever it was read from
// (the site's API export, a corpus record, or a folder of .glsl files).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "driver/dialect.h"

namespace shaderport::driver::project {

// Where a project came from; decides how `fix --in-place` writes it back.
enum class ProjectFormat {
  kApiExport,     // {"Shader": {"info": {...}, "renderpass": [...]}} (or a list of them)
  kCorpusRecord,  // {"id", "name", "author", "license", "passes": [...]} (one per line in .jsonl)
  kFolder,        // common.glsl, buffer-a.glsl ... image.glsl and project.toml
};

// What a channel reads, as the site names it in an input's `ctype`.
enum class ChannelSource {
  kNone,        // nothing bound: samples (0,0,0,1), iChannelResolution 0
  kBuffer,      // Buffer A-D (`buffer` = 0..3)
  kCubeBuffer,  // the Cube A pass (a cube map drawn by the project)
  kTexture,     // a 2D image (media file or user-given)
  kCubemap,     // a cube-map image
  kVolume,      // a 3D texture
  kKeyboard,    // the 256x3 keyboard state texture
  kVideo,       // video, webcam: a 2D texture that changes
  kAudio,       // music, musicstream, mic: the 512x2 FFT/wave texture
};

struct Sampler {
  std::string filter = "mipmap";  // nearest | linear | mipmap
  std::string wrap = "repeat";    // clamp | repeat
  bool vflip = true;
  bool srgb = false;
  std::string internal = "byte";  // byte | float (buffers on the site are float)
};

struct ChannelBinding {
  int channel = 0;  // 0..3
  ChannelSource source = ChannelSource::kNone;
  int buffer = -1;    // kBuffer: 0..3 for Buffer A..D
  std::string ctype;  // as written ("texture", "buffer", "cubemap", ...)
  std::string src;    // as written ("/media/a/...png", "/media/previz/buffer00.png", a file)
  Sampler sampler;
};

// Position of a pass's code inside the document it was read from: the code string
// maps byte for byte to document bytes (through JSON escapes), so that findings and
// edits land on the right bytes of the JSON file.
struct CodeOrigin {
  uint32_t literal_begin = 0;  // the opening quote of the JSON string (JSON formats)
  uint32_t literal_end = 0;    // one past the closing quote
  // Document offset of each code byte (size code.size() + 1: the last entry is the
  // closing quote). Empty for a folder pass, whose code is its own file.
  std::vector<uint32_t> document_offsets;
};

struct ProjectPass {
  model::PassKind kind = model::PassKind::kImage;
  std::string name;  // the site's tab name: "Image", "Buffer A", "Common", "Cube A", "Sound"
  std::string code;
  std::vector<ChannelBinding> inputs;  // sorted by channel, at most one per channel
  int output_buffer = -1;              // Buffer passes: 0..3, the buffer this pass writes
  std::string file;                    // kFolder: the pass's own file (e.g. "dir/buffer-a.glsl")
  CodeOrigin origin;

  const ChannelBinding* Input(int channel) const;
};

struct ShaderToyProject {
  ProjectFormat format = ProjectFormat::kApiExport;
  std::string id;
  std::string name;
  std::string author;
  std::string license;  // corpus records only
  std::string description;
  std::vector<ProjectPass> passes;  // in the document's order

  const ProjectPass* Find(model::PassKind kind) const;  // the first of that kind
  const ProjectPass* Common() const { return Find(model::PassKind::kCommon); }
  // Buffer passes in the site's drawing order (A, B, C, D), then nothing else.
  std::vector<const ProjectPass*> BuffersInOrder() const;
};

// The site's tab names and the folder layout's file names.
std::optional<int> BufferIndexFromName(std::string_view tab_name);  // "Buffer C" -> 2
// "/media/previz/buffer02.png" (how the site names a buffer input) -> 2.
std::optional<int> BufferIndexFromSource(std::string_view src);
std::string BufferTabName(int index);                       // 2 -> "Buffer C"
std::string TabName(model::PassKind kind, int buffer = 0);  // the site's tab name of a kind
std::string FolderFileName(const ProjectPass& pass);        // "buffer-c.glsl", "image.glsl", ...

}  // namespace shaderport::driver::project
