// Porting (`shaderport port`) and fixing (`shaderport fix`) one file: the rule
// engine, then glslang on the result. A fix set that makes validation worse is
// narrowed; errors in the result are located in the user's original text.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "driver/dialect.h"
#include "driver/file_decision.h"
#include "driver/input_files.h"
#include "driver/read_input.h"
#include "rule/rule.h"
#include "source/edit.h"
#include "source/source_manager.h"

namespace shaderport::driver {

struct PortOptions {
  rule::PortMode mode = rule::PortMode::kPort;
  std::optional<Dialect> dialect;  // forced; else detected from the code
  std::optional<model::Stage> stage;
  // The ShaderToy tab the code is (from a project); implies the ShaderToy dialect.
  std::optional<model::PassKind> pass;
  const model::HarnessDialect* harness = nullptr;  // --dialect FILE
  model::GivenChannelKinds channels{};             // --channel; nullopt: decided from the code
  // Rules to run; empty: the registry's rules for `mode`.
  std::vector<const rule::Rule*> rules;
  bool validate = true;  // run glslang on the result (and narrow bad fix sets)
};

struct PortResult {
  const SourceFile* file = nullptr;  // the original, in the SourceManager
  std::string text;                  // the result
  SourceMap map;                     // text -> original
  DetectedKind kind;                 // how the original was read (decision.kind)
  FileDecision decision;             // what the original is (file_decision.h)
  model::Stage output_stage = model::Stage::kFragment;
  DiagnosticList diagnostics;  // what remains, located in the original
  DiagnosticList fixed;        // findings whose fixes were applied
  int rounds = 0;
  bool read_failed = false;      // the input could not be read: no text
  bool validated = false;        // glslang accepted the result
  bool narrowed = false;         // some fixes were dropped because they broke validation
  bool byte_order_mark = false;  // the input began with one (not in `file` or `text`)
  // The input breached a resource limit (docs/limits.md): `text` is the input, nothing
  // was fixed or validated, and a port has no output.
  bool limit_breached = false;
  // False when the fixes did not settle (rules undoing each other, or still wanting
  // edits after the engine's last round): `text` is the input, and nothing is written.
  bool converged = true;

  bool Changed() const { return file != nullptr && text != file->Text(); }
  // A result that may be written or emitted: read, within the limits, settled.
  bool HasOutput() const { return !read_failed && !limit_breached && converged; }
};

// `file` (and `common`, ShaderToy's Common code) must live in `sources`.
PortResult PortSource(const SourceFile& file, const SourceFile* common, const PortOptions& options,
                      SourceManager& sources);

// Reads `path` (within the input limits) and ports or fixes it.
PortResult PortFile(const std::filesystem::path& path, const PortOptions& options,
                    SourceManager& sources);

// Ports or fixes contents read elsewhere (standard input) as the file `path`,
// which need not exist; a rejected input is reported on `path`.
PortResult PortInput(const std::filesystem::path& path, InputText input, const PortOptions& options,
                     SourceManager& sources);

// `options` for one input: its .shaderport.toml [[files]] dialect and stage apply
// where no flag gave them, as in `check`.
PortOptions OptionsFor(const PortOptions& options, const InputFile& input);

// The fix-mode shorthand.
inline PortResult FixFile(const std::filesystem::path& path, PortOptions options,
                          SourceManager& sources) {
  options.mode = rule::PortMode::kFix;
  return PortFile(path, options, sources);
}

}  // namespace shaderport::driver
