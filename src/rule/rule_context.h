// Everything a rule may read about one shader, and where it reports.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"
#include "glsl/lex/lexer.h"
#include "glsl/lex/preprocessor.h"
#include "glsl/sema/semantic_model.h"
#include "glsl/syntax/ast.h"
#include "model/channel_kind.h"
#include "model/harness_dialect.h"
#include "model/stage.h"
#include "model/target.h"
#include "model/webgl_extensions.h"
#include "rule/macro_fixes.h"
#include "source/source_file.h"

namespace shaderport::rule {

enum class PortMode {
  kFix,   // keep the file's dialect (a ShaderToy file stays a ShaderToy file)
  kPort,  // produce WebGL2 GLSL ES 3.00 with a real main()
};

struct PortSettings {
  PortMode mode = PortMode::kPort;
  model::Stage stage = model::Stage::kFragment;
  // The harness the code was written for: ShaderToy, glslsandbox, ..., or none
  // (plain WebGL1/WebGL2 code).
  const model::HarnessDialect* harness = nullptr;
  int source_version = 100;  // the code's own GLSL ES version: 100 or 300
  // Sampler kind chosen for each ShaderToy channel; nullopt lets the ShaderToy rule
  // infer it from how the code samples the channel.
  model::GivenChannelKinds channels{};
  model::Target target = model::Target::kWebGL2;
  model::EnabledExtensions extensions;  // what the page enabled (--enabled-extensions)
  // The #version line as written (0 when absent), for rules about the line itself.
  int written_version = 0;
  // The code is one of the harness's off-screen buffer passes (a ShaderToy Buffer tab).
  bool buffer_pass = false;
  // ShaderToy code as the site compiles it: after the site's header (#version,
  // precision, uniforms and its own `out vec4`), which the rules do not see.
  bool behind_site_header = false;
};

// A read-only view of the analysed shader plus a sink for findings.
class RuleContext {
 public:
  RuleContext(const SourceFile& file, const glsl::LexedFile& lexed,
              const glsl::PreprocessResult& preprocessed, const glsl::SyntaxTree& tree,
              const glsl::SemanticModel& model, const PortSettings& settings)
      : file_(file),
        lexed_(lexed),
        preprocessed_(preprocessed),
        tree_(tree),
        model_(model),
        settings_(settings) {}

  const SourceFile& File() const { return file_; }
  std::string_view Text() const { return file_.Text(); }
  const glsl::LexedFile& Lexed() const { return lexed_; }
  const glsl::PreprocessResult& Preprocessed() const { return preprocessed_; }
  const glsl::SyntaxTree& Tree() const { return tree_; }
  const glsl::SemanticModel& Model() const { return model_; }
  const PortSettings& Settings() const { return settings_; }

  // The source text a range covers (empty for ranges in other files).
  std::string_view TextOf(const SourceRange& range) const;

  // True when the bytes of `range` were written inside a macro body or come from
  // a macro expansion: a fix there is only safe when every expansion agrees
  // (see rule/macro_fixes.h).
  bool InMacro(const SourceRange& range) const;

  // Reports a finding. Fix-its that touch macro-expanded text are dropped with a
  // note ("not fixed automatically: inside macro 'X'") unless the rule checked
  // agreement itself and set `allow_in_macro`.
  void Report(Diagnostic diagnostic, bool allow_in_macro = false);

  // Called by the engine after the rule ran: settles the fixes that edit macro
  // bodies (see MacroFixAgreement) and hands over everything reported.
  DiagnosticList TakeDiagnostics();
  const DiagnosticList& Diagnostics() const { return diagnostics_; }

 private:
  const SourceFile& file_;
  const glsl::LexedFile& lexed_;
  const glsl::PreprocessResult& preprocessed_;
  const glsl::SyntaxTree& tree_;
  const glsl::SemanticModel& model_;
  const PortSettings& settings_;
  DiagnosticList diagnostics_;
  MacroFixAgreement macro_fixes_{preprocessed_};
  bool over_limit_ = false;
};

}  // namespace shaderport::rule
