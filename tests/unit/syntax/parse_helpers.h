// Shared helpers of the syntax tests: preprocess and parse text, check ranges.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "glsl/lex/preprocessor.h"
#include "glsl/syntax/parser.h"
#include "glsl/syntax/visit.h"
#include "source/source_manager.h"

namespace shaderport::glsl::testing {

struct Parsed {
  SourceManager sources;
  PreprocessResult pp;
  ParseResult result;

  const TranslationUnit& Root() const { return *result.tree.Root(); }
  std::vector<std::string> Messages() const {
    std::vector<std::string> out;
    for (const auto& d : result.diagnostics) out.push_back(d.rule_id + ": " + d.message);
    return out;
  }
  std::string Dump() const { return DumpAst(result.tree, sources); }
};

// Parses `texts` as one unit (e.g. ShaderToy Common + pass). The version comes
// from #version when present, else `default_version`.
inline std::unique_ptr<Parsed> ParseFiles(const std::vector<std::string>& texts,
                                          int default_version = 300) {
  auto parsed = std::make_unique<Parsed>();
  std::vector<const SourceFile*> files;
  for (size_t i = 0; i < texts.size(); ++i) {
    files.push_back(&parsed->sources.Add("f" + std::to_string(i) + ".glsl", texts[i]));
  }
  parsed->pp = Preprocess(files);
  ParseOptions options;
  options.version = parsed->pp.version.present ? parsed->pp.version.number : default_version;
  parsed->result = Parse(parsed->pp, options);
  return parsed;
}

inline std::unique_ptr<Parsed> ParseText(const std::string& text, int default_version = 300) {
  return ParseFiles({text}, default_version);
}

// Problems with the tree's structure: ids, reachability, range nesting.
inline std::vector<std::string> CheckTreeShape(const Parsed& parsed) {
  std::vector<std::string> problems;
  const SyntaxTree& tree = parsed.result.tree;
  for (uint32_t i = 0; i < tree.NodeCount(); ++i) {
    if (tree.NodeAt(i).id != i) problems.push_back("id mismatch at " + std::to_string(i));
  }
  std::vector<int> seen(tree.NodeCount(), 0);
  VisitPreorder(tree, [&](const Node& node, uint32_t) {
    ++seen[node.id];
    const SourceRange& r = node.range;
    if (!r.Valid() || r.file >= parsed.sources.Size() ||
        r.end > parsed.sources.Get(r.file).Text().size() || r.begin > r.end) {
      problems.push_back(std::string("bad range on ") + NodeKindName(node.kind));
    }
    ForEachChild(node, [&](const Node& child) {
      if (child.range.file == r.file && !r.Contains(child.range)) {
        problems.push_back(std::string(NodeKindName(child.kind)) + " outside its " +
                           NodeKindName(node.kind));
      }
    });
    return true;
  });
  for (uint32_t i = 0; i < tree.NodeCount(); ++i) {
    if (seen[i] != 1)
      problems.push_back("node " + std::to_string(i) + " reached " + std::to_string(seen[i]) +
                         " times");
  }
  return problems;
}

}  // namespace shaderport::glsl::testing
