// Runs glslang in validation mode (EShClientNone) on named source strings and
// returns its raw logs. Callable from several threads at once.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "model/stage.h"

namespace shaderport::validate {

// glslang's process-wide set-up, done once whichever thread asks first.
void InitializeGlslangOnce();

struct GlslangPart {
  std::string name;  // printed by glslang as "<name>:<line>"; must not contain ':'
  std::string_view text;
};

struct GlslangRun {
  bool ran = false;      // false when glslang could not be run at all (see crashed)
  bool crashed = false;  // glslang crashed or hung (isolated runs only)
  bool compiled = false;
  bool linked = false;  // only meaningful when linking was requested and compiled
  std::string compile_log;
  std::string link_log;
};

// Parses (EShMsgCascadingErrors: every error, not only the first) and links when
// `link` is set, on a thread with a large stack. `default_version` applies when the
// text has no #version (100 for WebGL1 input).
GlslangRun RunGlslang(std::span<const GlslangPart> parts, model::Stage stage, int default_version,
                      bool link);

// The same in a forked child process, for input known to make glslang recurse
// without bound: a crash or a hang (over `timeout_ms`) is reported, not suffered.
GlslangRun RunGlslangIsolated(std::span<const GlslangPart> parts, model::Stage stage,
                              int default_version, bool link, int timeout_ms = 10000);

}  // namespace shaderport::validate
