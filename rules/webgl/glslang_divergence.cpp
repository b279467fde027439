#include "rules/webgl/glslang_divergence.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "glsl/sema/builtins.h"
#include "glsl/syntax/visit.h"
#include "rules/webgl/constant_expression.h"
#include "rules/webgl/directive_text.h"
#include "rules/webgl/glslang_only_functions.h"
#include "rules/webgl/webgl_support.h"

namespace shaderport::rules {
namespace {

bool InFile(const BrowserContext& context, const Diagnostic& diagnostic) {
  return context.file != nullptr && diagnostic.range.file == context.file->Id();
}

uint32_t LineOf(const BrowserContext& context, uint32_t offset) {
  return context.file->LocationOf(offset).line;
}

// The declarators on the diagnostic's line (glslang places a declaration's error at
// the start of the line's first statement, so any of them may be the one it means).
std::vector<const glsl::Declarator*> DeclaratorsOnLine(const BrowserContext& context,
                                                       const Diagnostic& diagnostic) {
  const uint32_t line = LineOf(context, diagnostic.range.begin);
  std::vector<const glsl::Declarator*> found;
  glsl::VisitPreorder(*context.tree, [&](const glsl::Node& node, uint32_t) {
    const auto* declarator = node.As<glsl::Declarator>();
    if (declarator == nullptr || declarator->range.file != context.file->Id())
      return !node.IsExpr();
    if (LineOf(context, declarator->range.begin) <= line &&
        line <= LineOf(context, declarator->range.end)) {
      found.push_back(declarator);
    }
    return false;
  });
  return found;
}

bool InitializerFitsDeclaration(const BrowserContext& context, const glsl::Declarator& declarator) {
  const uint32_t symbol = context.model->SymbolAt(declarator.id);
  if (symbol == glsl::kNoSymbol) return false;
  const glsl::Type& declared = context.model->symbols[symbol].type;
  const glsl::Type& value = context.model->TypeOf(declarator.initializer->id);
  return value.IsUnknown() || value == declared;
}

bool IsConstDeclarator(const BrowserContext& context, const glsl::Declarator& declarator) {
  const uint32_t symbol = context.model->SymbolAt(declarator.id);
  return symbol != glsl::kNoSymbol && context.model->symbols[symbol].is_const;
}

void Demote(Diagnostic& diagnostic, Severity severity, const std::string& why) {
  diagnostic.severity = severity;
  diagnostic.notes.push_back({{}, why});
}

// A global initialised by what browsers fold to a constant (`float T = 2. * asinh(1.);`,
// `uintBitsToFloat(0x7f800001u)`): a constant initialiser to them, in either version;
// glslang folds fewer built-ins and calls it non-constant.
bool AllFolded(const BrowserContext& context, Diagnostic& diagnostic) {
  // A sequence of constants (`(1.0, 2.0)`) counts in both versions: ANGLE refuses it in
  // GLSL ES 3.00 only as a `const` declaration's initialiser.
  const webgl::ConstantRules rules{100, nullptr};
  bool folded = false;
  for (const glsl::Declarator* declarator : DeclaratorsOnLine(context, diagnostic)) {
    if (declarator->initializer == nullptr) continue;
    const uint32_t symbol = context.model->SymbolAt(declarator->id);
    if (symbol == glsl::kNoSymbol || context.model->symbols[symbol].scope != 0) continue;
    if (!webgl::IsConstantExpression(*context.model, *declarator->initializer, rules) ||
        !InitializerFitsDeclaration(context, *declarator)) {
      return false;
    }
    folded = true;
  }
  if (!folded) return false;
  Demote(diagnostic, Severity::kNote,
         "not an error in browsers: this initialiser is a constant expression (GLSL ES section "
         "4.3.3) that browsers fold; glslang cannot fold it");
  return true;
}

// GLSL ES 1.00 globals initialised from uniforms or other globals: browsers warn
// (WebGL 1.0 spec, "GLSL ES Global Variable Initialization"); GLSL ES 3.00 errors.
bool AlignGlobalInitializer(const BrowserContext& context, Diagnostic& diagnostic) {
  if (diagnostic.rule_id != "glslang/non-constant-global-initializer" &&
      diagnostic.message.find("non-constant global initializer") == std::string::npos) {
    return false;
  }
  if (AllFolded(context, diagnostic)) return true;
  if (context.version >= 300) return false;
  // Only uniforms, other globals and constants, with operators and math built-ins: a
  // built-in input such as gl_FragCoord, an attribute or varying, a call of the shader's
  // own function or of a texture or derivative built-in, an assignment or ++/-- is an
  // error there too ("global variable initializers must be constant expressions
  // (uniforms and globals are allowed)").
  const uint32_t line = LineOf(context, diagnostic.range.begin);
  bool found = false;
  bool allowed = true;
  std::set<uint32_t> inputs;  // declarators of attributes and varyings
  for (const glsl::Node* node : context.tree->Root()->declarations) {
    const auto* declaration = node->As<glsl::VariableDeclaration>();
    if (declaration == nullptr || (!declaration->qualifiers.Has(glsl::QualifierKind::kAttribute) &&
                                   !declaration->qualifiers.Has(glsl::QualifierKind::kVarying))) {
      continue;
    }
    for (const glsl::Declarator* declarator : declaration->declarators) {
      inputs.insert(declarator->id);
    }
  }
  for (const glsl::Node* node : context.tree->Root()->declarations) {
    const auto* declaration = node->As<glsl::VariableDeclaration>();
    if (declaration == nullptr) continue;
    for (const glsl::Declarator* declarator : declaration->declarators) {
      if (declarator->initializer == nullptr || declarator->range.file != context.file->Id() ||
          LineOf(context, declarator->range.begin) > line ||
          line > LineOf(context, declarator->range.end)) {
        continue;
      }
      found = true;
      glsl::ForEachNodeOf(
          *context.tree, *declarator->initializer,
          {glsl::NodeKind::kIdentifierExpr, glsl::NodeKind::kCallExpr,
           glsl::NodeKind::kAssignmentExpr, glsl::NodeKind::kUnaryExpr},
          [&](const glsl::Node& use) {
            if (use.kind == glsl::NodeKind::kAssignmentExpr) allowed = false;
            if (const auto* unary = use.As<glsl::UnaryExpr>()) {
              allowed = allowed && unary->op != glsl::UnaryOp::kPreIncrement &&
                        unary->op != glsl::UnaryOp::kPreDecrement &&
                        unary->op != glsl::UnaryOp::kPostIncrement &&
                        unary->op != glsl::UnaryOp::kPostDecrement;
              return;
            }
            if (const auto* call = use.As<glsl::CallExpr>();
                call != nullptr && call->call_kind == glsl::CallKind::kFunction) {
              const std::string& name = call->callee.text;
              if (name.starts_with("texture") || name.starts_with("shadow") ||
                  name.starts_with("dFd") || name == "fwidth") {
                allowed = false;
              }
            }
            const uint32_t symbol = context.model->SymbolAt(use.id);
            if (symbol == glsl::kNoSymbol) return;
            const glsl::Symbol& used = context.model->symbols[symbol];
            if (used.kind == glsl::SymbolKind::kFunction ||
                (used.kind == glsl::SymbolKind::kBuiltinVariable && !used.is_const) ||
                inputs.contains(used.declaration)) {
              allowed = false;
            }
          });
    }
  }
  if (!found || !allowed) return false;
  Demote(diagnostic, Severity::kWarning,
         "browsers accept non-constant global initialisers in GLSL ES 1.00 for legacy content "
         "and only warn (WebGL 1.0 spec, 'GLSL ES Global Variable Initialization'); glslang and "
         "GLSL ES 3.00 reject them");
  return true;
}

// `case 0: ;`, `case 0: {}` or `default: int;` at the end of a switch: browsers count
// the empty statement, block or declaration as the statement the last label needs
// (GLSL ES 3.00 section 6.2); glslang drops it first and reports the label bare.
bool AlignSwitchLastLabel(const BrowserContext& context, Diagnostic& diagnostic) {
  if (diagnostic.message.find("last case/default label not followed by statements") ==
      std::string::npos) {
    return false;
  }
  bool followed = false;
  glsl::VisitPreorder(*context.tree, [&](const glsl::Node& node, uint32_t) {
    const auto* statement = node.As<glsl::SwitchStatement>();
    if (statement == nullptr || statement->body == nullptr ||
        node.range.file != diagnostic.range.file || node.range.begin != diagnostic.range.begin) {
      return true;
    }
    const std::vector<glsl::Node*>& body = statement->body->statements;
    followed = !body.empty() && body.back()->kind != glsl::NodeKind::kCaseLabel;
    return false;
  });
  if (!followed) return false;
  Demote(diagnostic, Severity::kNote,
         "not an error in browsers: an empty statement, block or declaration after the last "
         "label is the statement it needs; glslang does not count it");
  return true;
}

// `float[4];` in GLSL ES 3.00: a declaration of an array type that declares no name
// is an empty declaration to browsers (as `float;`); glslang wants a name. Its size
// is still checked by both (glslang's own errors stay), and with no size at all
// browsers reject it too ("empty array declaration needs to specify a size").
bool AlignNamelessArrayDeclaration(const BrowserContext& context, Diagnostic& diagnostic) {
  if (context.version < 300 ||
      diagnostic.message.find("expect an array name") == std::string::npos) {
    return false;
  }
  const uint32_t line = LineOf(context, diagnostic.range.begin);
  bool nameless_sized_array = false;
  glsl::ForEachNodeOf(
      *context.tree, {glsl::NodeKind::kVariableDeclaration}, [&](const glsl::Node& node) {
        const auto& declaration = *node.As<glsl::VariableDeclaration>();
        if (declaration.type == nullptr || declaration.type->array.empty() ||
            node.range.file != context.file->Id() || LineOf(context, node.range.begin) != line) {
          return;
        }
        const bool sized = std::all_of(
            declaration.type->array.begin(), declaration.type->array.end(),
            [](const glsl::ArrayDimension& dimension) { return dimension.size != nullptr; });
        const bool nameless =
            declaration.declarators.empty() || declaration.declarators.front()->name.Empty();
        nameless_sized_array = nameless_sized_array || (sized && nameless);
      });
  if (!nameless_sized_array) return false;
  Demote(diagnostic, Severity::kNote,
         "not an error in browsers: in GLSL ES 3.00 a declaration of an array type with no "
         "name declares nothing, as 'float;' does; glslang asks for a name");
  return true;
}

// `const` initialisers and array sizes that are constant expressions glslang cannot
// fold (`vec4(0.5).x`, `matrixCompMult(m, m)`, `(2, 3)`): browsers fold them.
bool AlignConstantExpression(const BrowserContext& context, Diagnostic& diagnostic) {
  const bool initializer =
      diagnostic.message.find("non-constant initializer") != std::string::npos ||
      diagnostic.message.find("const initializers must be constant") != std::string::npos;
  const bool array_size =
      diagnostic.message.find("array size must be a constant") != std::string::npos;
  if (!initializer && !array_size) return false;
  const webgl::ConstantRules rules{context.version, nullptr};
  // Every declaration on the line that glslang could mean must be one browsers fold.
  bool constant = false;
  for (const glsl::Declarator* declarator : DeclaratorsOnLine(context, diagnostic)) {
    if (initializer) {
      if (declarator->initializer == nullptr || !IsConstDeclarator(context, *declarator)) continue;
      // The value must also have the declared type: `const vec4 c = (0.0, 1.0);` is a
      // float, which browsers reject ("dimension mismatch").
      if (!webgl::IsConstantExpression(*context.model, *declarator->initializer, rules) ||
          !InitializerFitsDeclaration(context, *declarator)) {
        return false;
      }
    } else {
      if (declarator->array.empty()) continue;
      // A size must be an integer too: `float a[3.5e38];` is constant, and browsers
      // reject it as glslang does.
      for (const glsl::ArrayDimension& dimension : declarator->array) {
        if (dimension.size == nullptr || !context.model->TypeOf(dimension.size->id).IsScalar() ||
            !context.model->TypeOf(dimension.size->id).IsIntegral() ||
            !webgl::IsConstantExpression(*context.model, *dimension.size, rules)) {
          return false;
        }
      }
    }
    constant = true;
  }
  if (!constant) return false;
  Demote(diagnostic, Severity::kNote,
         "not an error in browsers: this is a constant expression (GLSL ES section 4.3.3) that "
         "browsers fold; glslang cannot fold it");
  return true;
}

// glslang errors on what browsers only warn about or do not check at all.
bool AlignLenientMessages(const BrowserContext& context, Diagnostic& diagnostic) {
  const std::string& message = diagnostic.message;
  auto has = [&](std::string_view text) { return message.find(text) != std::string::npos; };
  if (has("names containing consecutive underscores are reserved") && has("#define")) {
    Demote(diagnostic, Severity::kWarning,
           "browsers only warn about a macro name with two consecutive underscores ('macro "
           "name with a double underscore is reserved'); other names with them are errors "
           "(webgl/reserved-name)");
    return true;
  }
  if (has("must have the same parameter precision qualifiers")) {
    Demote(diagnostic, Severity::kNote,
           "not an error in browsers: a prototype and the definition may give a parameter "
           "different precisions (say, when a 'precision' statement between them changed the "
           "default); glslang rejects it");
    return true;
  }
  if (context.version < 300 &&
      (has("numeric literal too big") || has("hexadecimal literal too big"))) {
    Demote(diagnostic, Severity::kWarning,
           "browsers only warn about an integer literal too big for 32 bits in GLSL ES 1.00 "
           "('Integer overflow'); it is an error in GLSL ES 3.00");
    return true;
  }
  if (has("cannot change qualification after use")) {
    Demote(diagnostic, Severity::kNote,
           "not an error in browsers: 'invariant' may be declared for a built-in output after "
           "it is written");
    return true;
  }
  if (const size_t at = message.find("extension not supported: "); at != std::string::npos) {
    const std::string name = message.substr(at + 25);
    if (model::ExtensionAvailable(name, context.target, context.extensions)) {
      Demote(diagnostic, Severity::kNote,
             "not an error in browsers: the WebGL context offers " + name +
                 " and a page enables it for this shader; glslang does not know it");
      return true;
    }
  }
  if (context.stage == model::Stage::kVertex && has("overlapping use of location")) {
    Demote(diagnostic, Severity::kNote,
           "not an error in browsers: vertex inputs may share a location when a stage is "
           "compiled (aliasing is only checked when a program is linked)");
    return true;
  }
  return false;
}

// glslang crashing is glslang's bug; when our own front end and the WebGL rules
// found nothing, the browser's verdict is most likely "compiles".
bool AlignCrash(const BrowserContext& context, Diagnostic& diagnostic) {
  if (diagnostic.rule_id != "glslang/crashed" || context.front_end_errors) return false;
  Demote(diagnostic, Severity::kWarning,
         "shaderport's own parser and WebGL rules found no error; browsers compile such input");
  return true;
}

}  // namespace

void AlignWithBrowser(const BrowserContext& context, Diagnostic& diagnostic) {
  if (diagnostic.severity != Severity::kError) return;
  if (AlignCrash(context, diagnostic)) return;
  if (!InFile(context, diagnostic) || context.tree == nullptr) return;
  if (AlignLenientMessages(context, diagnostic)) return;
  if (AlignNamelessArrayDeclaration(context, diagnostic)) return;
  if (AlignSwitchLastLabel(context, diagnostic)) return;
  if (context.model == nullptr) return;
  if (AlignGlobalInitializer(context, diagnostic)) return;
  AlignConstantExpression(context, diagnostic);
}

}  // namespace shaderport::rules
