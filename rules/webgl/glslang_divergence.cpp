#include "rules/webgl/glslang_divergence.h"

#include <string>

#include "glsl/syntax/visit.h"
#include "rules/webgl/constant_expression.h"

namespace shaderport::rules {
namespace {

bool InFile(const BrowserContext& context, const Diagnostic& diagnostic) {
  return context.file != nullptr && diagnostic.range.file == context.file->Id();
}

uint32_t LineOf(const BrowserContext& context, uint32_t offset) {
  return context.file->LocationOf(offset).line;
}

// The declarator with an initializer or array size on the diagnostic's line.
const glsl::Declarator* DeclaratorOnLine(const BrowserContext& context,
                                         const Diagnostic& diagnostic, bool& global) {
  const uint32_t line = LineOf(context, diagnostic.range.begin);
  const glsl::Declarator* found = nullptr;
  glsl::VisitPreorder(*context.tree, [&](const glsl::Node& node, uint32_t depth) {
    if (found != nullptr) return false;
    const auto* declarator = node.As<glsl::Declarator>();
    if (declarator == nullptr || declarator->range.file != context.file->Id())
      return !node.IsExpr();
    if (LineOf(context, declarator->range.begin) <= line &&
        line <= LineOf(context, declarator->range.end)) {
      found = declarator;
      global = depth <= 2;  // translation unit > declaration > declarator
    }
    return false;
  });
  return found;
}

bool IsConstDeclarator(const BrowserContext& context, const glsl::Declarator& declarator) {
  const uint32_t symbol = context.model->SymbolAt(declarator.id);
  return symbol != glsl::kNoSymbol && context.model->symbols[symbol].is_const;
}

void Demote(Diagnostic& diagnostic, Severity severity, const std::string& why) {
  diagnostic.severity = severity;
  diagnostic.notes.push_back({{}, why});
}

// GLSL ES 1.00 globals initialised from uniforms or other globals: browsers warn
// (WebGL 1.0 spec, "GLSL ES Global Variable Initialization"); GLSL ES 3.00 errors.
bool AlignGlobalInitializer(const BrowserContext& context, Diagnostic& diagnostic) {
  if (diagnostic.rule_id != "glslang/non-constant-global-initializer" &&
      diagnostic.message.find("non-constant global initializer") == std::string::npos) {
    return false;
  }
  if (context.version >= 300) return false;
  Demote(diagnostic, Severity::kWarning,
         "browsers accept non-constant global initialisers in GLSL ES 1.00 for legacy content "
         "and only warn (WebGL 1.0 spec, 'GLSL ES Global Variable Initialization'); glslang and "
         "GLSL ES 3.00 reject them");
  return true;
}

// `const` initialisers and array sizes that are constant expressions glslang cannot
// fold (`vec4(0.5).x`, `matrixCompMult(m, m)`, `(2, 3)`): browsers fold them.
bool AlignConstantExpression(const BrowserContext& context, Diagnostic& diagnostic) {
  const bool initializer = diagnostic.message.find("non-constant initializer") != std::string::npos;
  const bool array_size =
      diagnostic.message.find("array size must be a constant") != std::string::npos;
  if (!initializer && !array_size) return false;
  bool global = false;
  const glsl::Declarator* declarator = DeclaratorOnLine(context, diagnostic, global);
  if (declarator == nullptr) return false;
  const webgl::ConstantRules rules{context.version, nullptr};
  bool constant = true;
  if (initializer) {
    constant = declarator->initializer != nullptr && IsConstDeclarator(context, *declarator) &&
               webgl::IsConstantExpression(*context.model, *declarator->initializer, rules);
  } else {
    for (const glsl::ArrayDimension& dimension : declarator->array) {
      constant = constant && dimension.size != nullptr &&
                 webgl::IsConstantExpression(*context.model, *dimension.size, rules);
    }
    constant = constant && !declarator->array.empty();
  }
  if (!constant) return false;
  Demote(diagnostic, Severity::kNote,
         "not an error in browsers: this is a constant expression (GLSL ES section 4.3.3) that "
         "browsers fold; glslang cannot fold it");
  return true;
}

// glslang crashing is glslang's bug; when our own front end and the WebGL rules
// found nothing, the browser's verdict is most likely "compiles".
bool AlignCrash(const BrowserContext& context, Diagnostic& diagnostic) {
  if (diagnostic.rule_id != "glslang/crashed" || context.front_end_errors) return false;
  Demote(diagnostic, Severity::kWarning,
         "shaderport's own parser and WebGL rules found no error; browsers compile such input");
  return true;
}

// A `//` comment ending in a backslash continues on the next line (GLSL ES 3.00
// section 3.2 joins lines before comments are removed), as browsers do; glslang
// compiles the continued text as code.
bool AlignContinuedComment(const BrowserContext& context, Diagnostic& diagnostic) {
  if (diagnostic.rule_id != "glslang/syntax-error" || context.lexed == nullptr ||
      context.front_end_errors) {
    return false;
  }
  const std::string_view text = context.file->Text();
  for (const glsl::Trivia& trivia : context.lexed->trivia) {
    if (trivia.kind != glsl::TriviaKind::kLineComment) continue;
    const std::string_view comment = text.substr(trivia.begin, trivia.end - trivia.begin);
    const bool continued = comment.find("\\\n") != std::string_view::npos ||
                           comment.find("\\\r") != std::string_view::npos ||
                           (trivia.end < text.size() && text[trivia.end] == '\\');
    if (!continued) continue;
    Demote(diagnostic, Severity::kNote,
           "not an error in browsers: a '//' comment on line " +
               std::to_string(LineOf(context, trivia.begin)) +
               " ends in a backslash, which continues the comment on the next line (GLSL ES "
               "3.00 section 3.2); glslang compiles that next line as code");
    return true;
  }
  return false;
}

}  // namespace

void AlignWithBrowser(const BrowserContext& context, Diagnostic& diagnostic) {
  if (diagnostic.severity != Severity::kError) return;
  if (AlignCrash(context, diagnostic)) return;
  if (!InFile(context, diagnostic) || context.tree == nullptr) return;
  if (AlignContinuedComment(context, diagnostic)) return;
  if (context.model == nullptr) return;
  if (AlignGlobalInitializer(context, diagnostic)) return;
  AlignConstantExpression(context, diagnostic);
}

}  // namespace shaderport::rules
