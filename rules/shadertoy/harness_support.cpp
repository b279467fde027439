#include "rules/shadertoy/harness_support.h"

#include "glsl/sema/builtins.h"
#include "glsl/syntax/keywords.h"
#include "glsl/syntax/visit.h"

namespace shaderport::rules::harness {

const model::EntryPoint* DefinedEntryPoint(const model::HarnessDialect& dialect,
                                           const rule::CodeInterface& code) {
  for (const model::EntryPoint& entry : dialect.entry_points) {
    if (code.defined_functions.contains(entry.function)) return &entry;
  }
  return nullptr;
}

const glsl::FunctionDeclaration* FindDefinition(const rule::RuleContext& context,
                                                std::string_view name) {
  const auto* root = context.Tree().Root();
  if (root == nullptr) return nullptr;
  for (const glsl::Node* node : root->declarations) {
    const auto* function = node == nullptr ? nullptr : node->As<glsl::FunctionDeclaration>();
    if (function != nullptr && function->body != nullptr && function->name.text == name) {
      return function;
    }
  }
  return nullptr;
}

FreshNames::FreshNames(const rule::RuleContext& context) {
  for (const glsl::Token& token : context.Lexed().tokens) {
    if (token.kind == glsl::TokenKind::kIdentifier) used_.insert(std::string(token.text));
  }
  for (const glsl::PpToken& token : context.Preprocessed().tokens) {
    if (token.kind == glsl::TokenKind::kIdentifier) used_.insert(std::string(token.text));
  }
}

bool FreshNames::Taken(std::string_view name) const {
  if (name.starts_with("gl_") || name.find("__") != std::string_view::npos) return true;
  if (glsl::ClassifyWord(name, 300).status != glsl::WordStatus::kIdentifier) return true;
  if (glsl::IsBuiltinFunctionName(name)) return true;
  return used_.contains(name);
}

std::string FreshNames::Make(std::string_view base) {
  std::string name(base);
  // The shader has finitely many identifiers, so this ends; the bound is a guard.
  for (int n = 1; Taken(name) && n < 1'000'000; ++n) {
    name = std::string(base) + "_" + std::to_string(n);
  }
  used_.insert(name);
  return name;
}

std::optional<uint32_t> AfterVersionLines(const rule::RuleContext& context) {
  const auto& tokens = context.Lexed().tokens;
  const SourceFile& file = context.File();
  std::optional<uint32_t> offset;
  for (size_t i = 0; i + 1 < tokens.size(); ++i) {
    if (tokens[i].kind != glsl::TokenKind::kHash) break;
    const glsl::Token& word = tokens[i + 1];
    const bool is_version = word.text == "version";
    if (word.at_line_start || (!is_version && word.text != "extension")) break;
    if (!is_version && !offset) break;  // #extension before any #version: not ours to order
    size_t last = i + 1;
    while (last + 1 < tokens.size() && !tokens[last + 1].at_line_start &&
           tokens[last + 1].kind != glsl::TokenKind::kEndOfFile) {
      ++last;
    }
    const uint32_t line = file.LocationOf(tokens[last].end).line;
    offset = line < file.LineCount() ? file.LineStart(line + 1)
                                     : static_cast<uint32_t>(file.Text().size());
    i = last;
  }
  return offset;
}

std::set<std::string, std::less<>> DefinedMacros(const rule::RuleContext& context) {
  std::set<std::string, std::less<>> names;
  const auto& tokens = context.Lexed().tokens;
  for (size_t i = 0; i + 2 < tokens.size(); ++i) {
    if (tokens[i].kind == glsl::TokenKind::kHash && tokens[i + 1].text == "define" &&
        !tokens[i + 2].at_line_start) {
      names.insert(std::string(tokens[i + 2].text));
    }
  }
  return names;
}

namespace {

// Which sampler a texture call's coordinate implies: 2 or 3 components, or 0 when
// the call says nothing (textureSize, texelFetch, unknown types).
int CoordinateSize(const glsl::SemanticModel& model, const glsl::CallExpr& call) {
  const std::string_view name = call.callee.text;
  if (name.starts_with("textureCube")) return 3;
  if (name.starts_with("texture2D")) return 2;
  const bool sampling = name == "texture" || name == "textureLod" || name == "textureGrad" ||
                        name == "textureOffset" || name == "textureLodOffset" ||
                        name == "textureGradOffset";
  if (!sampling || call.arguments.size() < 2 || call.arguments[1] == nullptr) return 0;
  const glsl::Type& type = model.TypeOf(call.arguments[1]->id);
  if (type.base != glsl::BaseType::kFloat || type.IsArray() || type.columns != 1) return 0;
  return type.rows == 2 || type.rows == 3 ? type.rows : 0;
}

}  // namespace

std::array<ChannelUse, 4> ReadChannelUses(const glsl::SyntaxTree& tree,
                                          const glsl::SemanticModel& model,
                                          const std::array<std::string, 4>& names) {
  std::array<ChannelUse, 4> uses;
  glsl::VisitPreorder(tree, [&](const glsl::Node& node, uint32_t) {
    const auto* call = node.As<glsl::CallExpr>();
    if (call == nullptr || !call->callee.text.starts_with("texture") || call->arguments.empty() ||
        call->arguments[0] == nullptr) {
      return true;
    }
    const auto* sampler = call->arguments[0]->As<glsl::IdentifierExpr>();
    if (sampler == nullptr) return true;
    for (size_t channel = 0; channel < names.size(); ++channel) {
      if (names[channel].empty() || sampler->name != names[channel]) continue;
      const int size = CoordinateSize(model, *call);
      ChannelUse& use = uses[channel];
      if (size == 2 && use.first_2d == glsl::kNoNode) use.first_2d = call->id;
      if (size == 3 && use.first_cube == glsl::kNoNode) use.first_cube = call->id;
    }
    return true;
  });
  return uses;
}

std::array<std::string, 4> ChannelNames(const model::HarnessDialect& dialect) {
  std::array<std::string, 4> names;
  for (const model::ProvidedVariable& provided : dialect.provides) {
    if (provided.channel >= 0 && provided.channel < 4) names[provided.channel] = provided.name;
  }
  return names;
}

std::array<ChannelChoice, 4> ChooseChannels(const rule::RuleContext& context,
                                            const model::HarnessDialect& dialect) {
  std::array<ChannelChoice, 4> choices;
  const std::array<ChannelUse, 4> uses =
      ReadChannelUses(context.Tree(), context.Model(), ChannelNames(dialect));
  for (size_t channel = 0; channel < choices.size(); ++channel)
    choices[channel].use = uses[channel];
  for (size_t channel = 0; channel < choices.size(); ++channel) {
    ChannelChoice& choice = choices[channel];
    if (const std::optional<model::ChannelKind> told = context.Settings().channels[channel]) {
      choice.type = model::SamplerTypeName(*told);
      choice.told = true;
    } else {
      choice.type = choice.use.OnlyCube() ? "samplerCube" : "sampler2D";
    }
  }
  return choices;
}

std::string TypeFor(const model::ProvidedVariable& variable,
                    const std::array<ChannelChoice, 4>& channels) {
  if (variable.channel >= 0 && variable.channel < 4) return channels[variable.channel].type;
  return variable.type;
}

}  // namespace shaderport::rules::harness
