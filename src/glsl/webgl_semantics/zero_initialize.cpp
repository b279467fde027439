// Locals and globals declared without an initializer get ` = <zero>`, as ANGLE's
// InitializeUninitializedLocals and DeferGlobalInitializers do for WebGL; shader
// outputs (and gl_Position) are zeroed at the start of main(), as its
// initOutputVariables / initGLPosition do. Arrays longer than a constructor should
// spell are zeroed by a loop right after their declaration.
#include "glsl/syntax/visit.h"
#include "glsl/webgl_semantics/semantics_context.h"
#include "glsl/webgl_semantics/zero_value.h"

namespace shaderport::glsl {
namespace {

constexpr std::string_view kIndexName = "shaderport_i";

bool NeverInitialized(const QualifierList& qualifiers) {
  return qualifiers.Has(QualifierKind::kConst) || qualifiers.Has(QualifierKind::kUniform) ||
         qualifiers.Has(QualifierKind::kIn) || qualifiers.Has(QualifierKind::kInOut) ||
         qualifiers.Has(QualifierKind::kAttribute) || qualifiers.Has(QualifierKind::kVarying);
}

// `for (...) name[i] = zero;` for an array too long for a constructor.
std::optional<std::string> ZeroLoop(const std::string& name, const Type& type,
                                    const SemanticModel& model) {
  if (!type.IsArray() || type.array_size <= 0) return std::nullopt;
  const auto element = ZeroValue(type.Element(), model.structs, model.version);
  if (!element) return std::nullopt;
  const std::string i(kIndexName);
  return "for (int " + i + " = 0; " + i + " < " + std::to_string(type.array_size) + "; ++" + i +
         ") " + name + "[" + i + "] = " + *element + ";";
}

void Declaration(SemanticsContext& c, const VariableDeclaration& decl, MainPrologue& prologue) {
  const Node* parent = c.Parent(decl);
  if (parent == nullptr) return;
  const bool global = parent->kind == NodeKind::kTranslationUnit;
  const bool statement = parent->kind == NodeKind::kCompoundStatement;
  const bool in_loop_header =
      parent->kind == NodeKind::kForStatement || parent->kind == NodeKind::kWhileStatement;
  if (!global && !statement && !in_loop_header) return;  // struct fields, block members
  if (NeverInitialized(decl.qualifiers)) return;
  const bool output = decl.qualifiers.Has(QualifierKind::kOut);
  for (const Declarator* declarator : decl.declarators) {
    if (declarator->initializer != nullptr || declarator->name.Empty()) continue;
    const uint32_t symbol = c.model.SymbolAt(declarator->id);
    if (symbol == kNoSymbol) continue;
    const Type& type = c.model.symbols[symbol].type;
    const std::string& name = declarator->name.text;
    const auto zero = ZeroValue(type, c.model.structs, c.model.version);
    if (output || (global && !zero)) {
      // Outputs cannot have initializers; long global arrays are zeroed in main().
      if (zero) {
        prologue.statements.push_back(name + " = " + *zero + ";");
      } else if (auto loop = ZeroLoop(name, type, c.model)) {
        prologue.statements.push_back(std::move(*loop));
      } else {
        ++c.result.skipped;
        continue;
      }
      ++c.result.initialized;
      continue;
    }
    if (zero) {
      const auto span = c.edits.Span(*declarator);
      if (!span) {
        ++c.result.skipped;
        continue;
      }
      c.edits.Insert(span->file, span->end, " = " + *zero);
      ++c.result.initialized;
      continue;
    }
    const auto loop = ZeroLoop(name, type, c.model);
    const auto span = c.edits.Span(decl);
    if (!loop || !statement || !span) {
      ++c.result.skipped;
      continue;
    }
    c.edits.Insert(span->file, span->end, " " + *loop);
    ++c.result.initialized;
  }
}

void OutParameters(SemanticsContext& c, const FunctionDeclaration& function) {
  if (function.body == nullptr) return;
  std::string text;
  for (const ParameterDeclaration* parameter : function.parameters) {
    if (!parameter->qualifiers.Has(QualifierKind::kOut) || parameter->name.Empty()) continue;
    const uint32_t symbol = c.model.SymbolAt(parameter->id);
    if (symbol == kNoSymbol) continue;
    const auto zero = ZeroValue(c.model.symbols[symbol].type, c.model.structs, c.model.version);
    if (!zero) {
      ++c.result.skipped;
      continue;
    }
    text += " " + parameter->name.text + " = " + *zero + ";";
    ++c.result.initialized;
  }
  if (text.empty()) return;
  const auto at = c.edits.AfterOpeningBrace(*function.body);
  if (!at) {
    ++c.result.skipped;
    return;
  }
  c.edits.Insert(at->file, at->begin, text);
}

}  // namespace

void ZeroInitializeVariables(SemanticsContext& c, MainPrologue& prologue) {
  if (c.options.vertex_stage) prologue.statements.emplace_back("gl_Position = vec4(0.0);");
  VisitPreorder(c.tree, [&](const Node& node, uint32_t) {
    if (const auto* decl = node.As<VariableDeclaration>()) {
      Declaration(c, *decl, prologue);
      return true;
    }
    if (const auto* function = node.As<FunctionDeclaration>()) {
      if (c.options.zero_out_parameters) OutParameters(c, *function);
    }
    return true;
  });
}

}  // namespace shaderport::glsl
