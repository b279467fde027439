// Parses and analyses shader text for the sema tests.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "glsl/lex/preprocessor.h"
#include "glsl/sema/semantic_model.h"
#include "glsl/syntax/parser.h"
#include "source/source_manager.h"

namespace shaderport::glsl::testing {

struct Analyzed {
  SourceManager sources;
  PreprocessResult tokens;
  ParseResult parse;
  SemanticModel model;

  // The first expression (in source order) whose source text is exactly `text`, or nullptr.
  const Node* FindExpr(std::string_view text) const {
    const Node* best = nullptr;
    for (uint32_t id = 0; id < parse.tree.NodeCount(); ++id) {
      const Node& n = parse.tree.NodeAt(id);
      if (!n.IsExpr() || !n.range.Valid() || n.range.file >= sources.Size()) continue;
      std::string_view src = sources.Get(n.range.file).Text();
      if (n.range.end > src.size() || src.substr(n.range.begin, n.range.Size()) != text) continue;
      if (best == nullptr || n.range.begin < best->range.begin) best = &n;
    }
    return best;
  }
  std::string TypeOf(std::string_view text) const {
    const Node* n = FindExpr(text);
    return n == nullptr ? "<no such expression>" : model.Spell(model.TypeOf(n->id));
  }
  std::string TextOf(uint32_t node) const {
    const Node& n = parse.tree.NodeAt(node);
    return std::string(sources.Get(n.range.file).Text().substr(n.range.begin, n.range.Size()));
  }
};

// `files` are preprocessed as one unit (e.g. ShaderToy Common, then a pass).
inline std::unique_ptr<Analyzed> AnalyzeText(const std::vector<std::string>& files,
                                             AnalyzeOptions options) {
  auto a = std::make_unique<Analyzed>();
  std::vector<const SourceFile*> pointers;
  for (size_t i = 0; i < files.size(); ++i) {
    pointers.push_back(&a->sources.Add("file" + std::to_string(i) + ".glsl", files[i]));
  }
  a->tokens = Preprocess(pointers);
  ParseOptions parse_options;
  parse_options.version = options.version;
  a->parse = Parse(a->tokens, parse_options);
  a->model = Analyze(a->parse.tree, options);
  return a;
}

inline std::unique_ptr<Analyzed> AnalyzeText(const std::string& text, int version = 300,
                                             model::Stage stage = model::Stage::kFragment) {
  AnalyzeOptions options;
  options.version = version;
  options.stage = stage;
  return AnalyzeText(std::vector<std::string>{text}, options);
}

// ShaderToy's uniforms, as (name, type) pairs.
inline std::vector<std::pair<std::string, Type>> ShaderToyUniforms() {
  const Type vec3 = Type::Vector(BaseType::kFloat, 3);
  const Type vec4 = Type::Vector(BaseType::kFloat, 4);
  std::vector<std::pair<std::string, Type>> u = {{"iResolution", vec3},
                                                 {"iTime", Type::Float()},
                                                 {"iTimeDelta", Type::Float()},
                                                 {"iFrameRate", Type::Float()},
                                                 {"iFrame", Type::Int()},
                                                 {"iChannelTime", Type::Float().ArrayOf(4)},
                                                 {"iChannelResolution", vec3.ArrayOf(4)},
                                                 {"iMouse", vec4},
                                                 {"iDate", vec4},
                                                 {"iSampleRate", Type::Float()}};
  for (int i = 0; i < 4; ++i) {
    u.emplace_back("iChannel" + std::to_string(i), Type::Sampler(SamplerDim::k2D));
  }
  return u;
}

}  // namespace shaderport::glsl::testing
