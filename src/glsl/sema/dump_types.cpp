// DumpTypes: the expression types of a model as text, for `shaderport dump --types`
// and the sema goldens.
#include <algorithm>
#include <tuple>

#include "glsl/sema/semantic_model.h"

namespace shaderport::glsl {
namespace {

constexpr size_t kMaxShownText = 60;

// The node's source text on one line: whitespace runs become one space, long text is cut.
// Only the shown prefix is read: an operand chain `a+a+...` nests n expressions whose
// texts add up to n^2/2 bytes (400,000 terms took minutes).
std::string ShownText(std::string_view text) {
  std::string out;
  bool space = false;
  for (char c : text) {
    if (out.size() > kMaxShownText) break;
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') {
      space = true;
      continue;
    }
    if (space && !out.empty()) out += ' ';
    space = false;
    out += c;
  }
  if (out.size() > kMaxShownText) out = out.substr(0, kMaxShownText - 3) + "...";
  return out;
}

}  // namespace

std::string DumpTypes(const SyntaxTree& tree, const SemanticModel& model,
                      const SourceManager& sources) {
  std::vector<const Node*> exprs;
  for (uint32_t id = 0; id < tree.NodeCount(); ++id) {
    const Node& node = tree.NodeAt(id);
    if (node.IsExpr() && node.range.Valid() && node.range.Size() > 0 &&
        node.range.file < sources.Size()) {
      exprs.push_back(&node);
    }
  }
  // Source order; an enclosing expression before the ones inside it.
  std::stable_sort(exprs.begin(), exprs.end(), [](const Node* a, const Node* b) {
    return std::tuple(a->range.file, a->range.begin, b->range.end) <
           std::tuple(b->range.file, b->range.begin, a->range.end);
  });
  std::string out;
  for (const Node* node : exprs) {
    const SourceFile& file = sources.Get(node->range.file);
    std::string_view text = file.Text();
    if (node->range.end > text.size()) continue;
    LineColumn at = file.LocationOf(node->range.begin);
    out += std::to_string(at.line) + ":" + std::to_string(at.column) + " '" +
           ShownText(text.substr(node->range.begin, node->range.Size())) +
           "' : " + model.Spell(model.TypeOf(node->id)) + "\n";
  }
  return out;
}

}  // namespace shaderport::glsl
