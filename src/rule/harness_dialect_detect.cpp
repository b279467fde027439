#include "rule/harness_dialect_detect.h"

#include "glsl/lex/preprocessor.h"
#include "glsl/syntax/parser.h"
#include "glsl/syntax/visit.h"

namespace shaderport::rule {
namespace {

// Weights: an entry point is decisive; a provided name the code needs but does not
// declare is strong; a name it declares itself, or a hint, is weak.
constexpr int kEntryPointScore = 10;
constexpr int kFreeNameScore = 3;
constexpr int kDeclaredNameScore = 1;
constexpr int kMinimumScore = 3;

void AddGlobals(const glsl::Node& declaration, CodeInterface& code) {
  if (const auto* variable = declaration.As<glsl::VariableDeclaration>()) {
    for (const glsl::Declarator* declarator : variable->declarators) {
      code.globals.insert(declarator->name.text);
    }
    if (variable->type != nullptr && variable->type->struct_def != nullptr) {
      code.globals.insert(variable->type->struct_def->name.text);
    }
  } else if (const auto* block = declaration.As<glsl::InterfaceBlock>()) {
    code.globals.insert(block->block_name.text);
    if (!block->instance_name.Empty()) code.globals.insert(block->instance_name.text);
    for (const glsl::VariableDeclaration* member : block->members) {
      for (const glsl::Declarator* declarator : member->declarators) {
        if (block->instance_name.Empty()) code.globals.insert(declarator->name.text);
      }
    }
  } else if (const auto* function = declaration.As<glsl::FunctionDeclaration>()) {
    code.functions.insert(function->name.text);
    if (function->body != nullptr) code.defined_functions.insert(function->name.text);
  }
}

}  // namespace

CodeInterface ReadCodeInterface(const glsl::SyntaxTree& tree, const glsl::SemanticModel& model) {
  CodeInterface code;
  if (tree.Root() == nullptr) return code;
  for (const glsl::Node* declaration : tree.Root()->declarations) {
    if (declaration != nullptr) AddGlobals(*declaration, code);
  }
  code.globals.erase("");
  glsl::VisitPreorder(tree, [&](const glsl::Node& node, uint32_t) {
    const auto* identifier = node.As<glsl::IdentifierExpr>();
    if (identifier != nullptr && model.SymbolAt(node.id) == glsl::kNoSymbol) {
      code.free_identifiers.insert(identifier->name);
    }
    return true;
  });
  return code;
}

std::optional<DialectMatch> DetectDialect(std::span<const model::HarnessDialect> candidates,
                                          const CodeInterface& code) {
  std::optional<DialectMatch> best;
  const bool has_main = code.defined_functions.contains("main");
  for (const model::HarnessDialect& dialect : candidates) {
    DialectMatch match{&dialect, 0, {}};
    bool entry_found = false;
    for (const model::EntryPoint& entry : dialect.entry_points) {
      if (!entry_found && !has_main && code.defined_functions.contains(entry.function)) {
        match.score += kEntryPointScore;
        match.evidence.push_back("defines " + entry.function + "() and no main()");
        entry_found = true;
      }
    }
    // A host whose users write an entry point never sees a main() of theirs.
    if (!dialect.entry_points.empty() && has_main) continue;
    auto weigh = [&](const std::string& name) {
      if (code.free_identifiers.contains(name)) {
        match.score += kFreeNameScore;
        match.evidence.push_back("uses " + name + " without declaring it");
      } else if (code.globals.contains(name)) {
        match.score += kDeclaredNameScore;
        match.evidence.push_back("declares " + name);
      }
    };
    for (const model::ProvidedVariable& provided : dialect.provides) weigh(provided.name);
    for (const auto& [from, to] : dialect.renames) weigh(from);
    for (const std::string& hint : dialect.hints) {
      if (!dialect.FindEntryPoint(hint)) weigh(hint);
    }
    if (match.score < kMinimumScore) continue;
    if (!best || match.score > best->score) best = std::move(match);
  }
  return best;
}

std::optional<DialectMatch> DetectDialectInText(std::span<const model::HarnessDialect> candidates,
                                                std::string_view text) {
  const SourceFile file(0, "<detect>", std::string(text));
  const SourceFile* files[] = {&file};
  const glsl::PreprocessResult preprocessed = glsl::Preprocess(files);
  glsl::ParseOptions parse_options;
  parse_options.version = preprocessed.version.number >= 300 ? 300 : 100;
  const glsl::ParseResult parsed = glsl::Parse(preprocessed, parse_options);
  glsl::AnalyzeOptions analyze;
  analyze.version = parse_options.version;
  const glsl::SemanticModel model = glsl::Analyze(parsed.tree, analyze);
  return DetectDialect(candidates, ReadCodeInterface(parsed.tree, model));
}

}  // namespace shaderport::rule
