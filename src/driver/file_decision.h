// What a file is, decided once, here, for every command (check, fix, port, render,
// report, explain-file): its dialect and ShaderToy pass, its stage, the harness that
// completes it, the sampler type of each channel and the WebGL target. What the user
// says (flags, then .shaderport.toml, then a project's own data) wins; the rest comes
// from the code, and every part keeps the reason it was chosen.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "driver/dialect.h"
#include "glsl/lex/lexer.h"
#include "glsl/sema/semantic_model.h"
#include "glsl/syntax/ast.h"
#include "model/harness_dialect.h"
#include "report/check_report.h"
#include "validate/glslang_validator.h"
#include "validate/shadertoy_contract.h"

namespace shaderport::driver {

// What the user said about a file; unset parts are decided from the code.
struct DecisionGiven {
  std::optional<Dialect> dialect;
  std::optional<model::Stage> stage;
  std::optional<model::PassKind> pass;
  std::optional<model::Target> target;
  const model::HarnessDialect* harness = nullptr;  // --dialect NAME|FILE.toml naming a harness
  std::array<std::optional<model::ChannelKind>, 4> channels{};
  // Where each given part came from, for people: "--dialect", "config ./.shaderport.toml".
  std::string dialect_from = "--dialect";
  std::string stage_from = "--stage";
  std::string target_from = "--target";
  std::string channels_from = "--channel";
};

// One decided part and why: {"dialect", "shadertoy", "defines mainImage() and no main()"}.
using DecisionReason = DecisionPart;

struct FileDecision {
  DetectedKind kind;
  model::Target target = model::Target::kWebGL2;
  // The host that completes the code: ShaderToy's for ShaderToy code, a detected or
  // given harness dialect (rules/dialects/) for code that uses its names, else none.
  const model::HarnessDialect* harness = nullptr;
  model::ChannelKinds channels{};  // iChannel0..3 (ShaderToy code)
  // A harness other than ShaderToy: the lines it puts before this code (its
  // prelude, defines and the declarations of what the code uses); "" when none.
  std::string harness_header;
  int harness_version = 0;  // the version its prelude sets (100 or 300), 0: the code's own
  std::vector<DecisionReason> reasons;

  bool IsShaderToy() const { return kind.dialect == Dialect::kShaderToy; }
  // The version the code is compiled as when its host forces one (0: its #version).
  int ForcedVersion() const { return IsShaderToy() ? 300 : harness_version; }
};

// The first half, from the file's tokens: dialect, pass, stage, target, the
// ShaderToy harness and given channels.
FileDecision DecideFromTokens(const glsl::LexedFile& lexed, const std::filesystem::path& path,
                              const DecisionGiven& given);

// The second half, from the front end's tree of the code as the first half saw it:
// a harness dialect for code that uses a host's names without declaring them, and the
// sampler type of each channel not given (a cube map when sampled only with 3-component
// coordinates). Returns true when the front end must run again to see what was decided
// (a harness header, a channel that is not 2D).
bool DecideFromTree(FileDecision& decision, const glsl::LexedFile& lexed,
                    const glsl::SyntaxTree& tree, const glsl::SemanticModel& model,
                    const DecisionGiven& given);

// What glslang compiles for `file` as the decision says its host composes it:
// ShaderToy's header, Common, the pass and the site's main(); a harness's header and
// the code; or the code alone. `common` is used for ShaderToy passes only.
validate::ValidationRequest ComposeForGlslang(const FileDecision& decision, const SourceFile& file,
                                              const SourceFile* common, SourceManager& sources);

// The whole decision for callers that do not keep the front end's result.
FileDecision DecideFile(const SourceFile& file, const SourceFile* common,
                        const DecisionGiven& given, SourceManager& sources);

}  // namespace shaderport::driver
