// portability/index-range: a dynamic index into a vector, matrix or sized array
// whose range of values is known and leaves the valid range. Browsers clamp every
// dynamic index for WebGL, so the code silently uses the last (or first) element;
// native GL, Vulkan, Metal and D3D read or write out of bounds.
//
//   vec3 col;
//   for (int c = 0; c < 8; c++) col[c] = f(c);   // c runs 0..7, col has 3 components
//
// The index's range comes from the interval analysis of value_range.h (loop
// bounds, constants, clamp/min/max, `% N`, `& N`, ...), narrowed by the guards
// around the index: `if (i < 3) col[i]`, `if (i > 2) break;` before it, the
// branches of `i == 6 ? 0 : i + 1`. Indices whose range is unknown are not
// reported, nor constant ones (a compile error already). No fix: the intended
// bound is the author's to choose.
#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "glsl/syntax/visit.h"
#include "rules/all_rules.h"
#include "rules/portability/portability_support.h"
#include "rules/portability/value_range.h"
#include "rules/webgl/constant_expression.h"

namespace shaderport::rules {
namespace {

constexpr std::string_view kId = "portability/index-range";
constexpr size_t kMaxTextInMessage = 40;

using portability::Overrides;
using portability::Range;
using portability::ValueRanges;

// Narrows variable ranges by the conditions that guard a piece of code: the
// if/?: conditions around it, the left side of && and || before it, and earlier
// `if (cond) break;` (continue, return, discard) in the same blocks.
class Guards {
 public:
  Guards(const rule::RuleContext& context, const ValueRanges& ranges)
      : context_(context), ranges_(ranges) {}

  // The overrides that hold at `node`.
  Overrides At(const glsl::Node& node) {
    if (parents_.empty()) BuildParents();
    Overrides overrides;
    const glsl::Node* child = &node;
    for (uint32_t up = parents_[node.id]; up != glsl::kNoNode; up = parents_[up]) {
      const glsl::Node& parent = context_.Tree().NodeAt(up);
      if (const auto* branch = parent.As<glsl::IfStatement>()) {
        if (child == branch->then_branch) ranges_.Assume(branch->condition, true, overrides);
        if (child == branch->else_branch) ranges_.Assume(branch->condition, false, overrides);
      } else if (const auto* conditional = parent.As<glsl::ConditionalExpr>()) {
        if (child == conditional->if_true) ranges_.Assume(conditional->condition, true, overrides);
        if (child == conditional->if_false)
          ranges_.Assume(conditional->condition, false, overrides);
      } else if (const auto* binary = parent.As<glsl::BinaryExpr>()) {
        if (child == binary->rhs && binary->op == glsl::BinaryOp::kLogicalAnd) {
          ranges_.Assume(binary->lhs, true, overrides);
        }
        if (child == binary->rhs && binary->op == glsl::BinaryOp::kLogicalOr) {
          ranges_.Assume(binary->lhs, false, overrides);
        }
      } else if (const auto* block = parent.As<glsl::CompoundStatement>()) {
        for (const glsl::Node* earlier : block->statements) {
          if (earlier == child) break;
          const auto* exit = earlier != nullptr ? earlier->As<glsl::IfStatement>() : nullptr;
          if (exit != nullptr && exit->else_branch == nullptr && Jumps(exit->then_branch)) {
            ranges_.Assume(exit->condition, false, overrides);
          }
        }
      } else if (parent.kind == glsl::NodeKind::kFunctionDeclaration) {
        break;
      }
      child = &parent;
    }
    return overrides;
  }

 private:
  void BuildParents() {
    parents_.assign(context_.Tree().NodeCount(), glsl::kNoNode);
    glsl::VisitPreorder(context_.Tree(), [&](const glsl::Node& node, uint32_t) {
      glsl::ForEachChild(node, [&](const glsl::Node& child) { parents_[child.id] = node.id; });
      return true;
    });
  }

  // A statement that leaves the block: break, continue, return, discard, or a
  // block ending with one.
  static bool Jumps(const glsl::Node* statement) {
    while (statement != nullptr) {
      switch (statement->kind) {
        case glsl::NodeKind::kBreakStatement:
        case glsl::NodeKind::kContinueStatement:
        case glsl::NodeKind::kReturnStatement:
        case glsl::NodeKind::kDiscardStatement:
          return true;
        case glsl::NodeKind::kCompoundStatement: {
          const auto& statements =
              static_cast<const glsl::CompoundStatement*>(statement)->statements;
          statement = statements.empty() ? nullptr : statements.back();
          break;
        }
        default:
          return false;
      }
    }
    return false;
  }

  const rule::RuleContext& context_;
  const ValueRanges& ranges_;
  std::vector<uint32_t> parents_;
};

std::string Quoted(const rule::RuleContext& context, const glsl::Expr& expr) {
  const std::string_view text = context.TextOf(expr.range);
  if (text.empty() || text.size() > kMaxTextInMessage || text.find('\n') != std::string::npos) {
    return {};
  }
  return std::string(text);
}

std::string Number(double value) { return std::to_string(static_cast<long long>(value)); }

class IndexRangeRule final : public rule::Rule {
 public:
  const rule::RuleInfo& Info() const override {
    static const rule::RuleInfo info{
        kId, "A dynamic index whose known range leaves the vector, matrix or array",
        "vec3 col;\nfor (int c = 0; c < 8; c++) col[c] = 0.5;", "", rule::RuleScope::kLint};
    return info;
  }

  void Run(rule::RuleContext& context) const override {
    if (context.Tree().Root() == nullptr) return;
    const glsl::SemanticModel& model = context.Model();
    ValueRanges ranges(context);
    Guards guards(context, ranges);
    std::unordered_set<uint32_t> written;  // index expressions that are written through
    portability::ForEachWrittenExpr(context, *context.Tree().Root(), [&](const glsl::Expr& target) {
      for (const glsl::Expr* e = &target; e != nullptr;) {
        if (const auto* paren = e->As<glsl::ParenExpr>()) {
          e = paren->inner;
        } else if (const auto* member = e->As<glsl::MemberExpr>()) {
          e = member->object;
        } else if (const auto* index = e->As<glsl::IndexExpr>()) {
          written.insert(index->id);
          e = index->base;
        } else {
          break;
        }
      }
    });
    const webgl::ConstantRules constant_rules{model.version, nullptr};
    glsl::ForEachNodeOf(context.Tree(), {glsl::NodeKind::kIndexExpr}, [&](const glsl::Node& node) {
      const auto* index = node.As<glsl::IndexExpr>();
      if (index->base == nullptr || index->index == nullptr) return;
      const glsl::Type& base = model.TypeOf(index->base->id);
      int size = 0;
      std::string noun;
      if (base.IsArray()) {
        size = base.array_size;
        noun = "elements";
      } else if (base.IsMatrix()) {
        size = base.columns;
        noun = "columns";
      } else if (base.IsVector()) {
        size = base.rows;
        noun = "components";
      }
      if (size <= 0) return;
      const glsl::Type& index_type = model.TypeOf(index->index->id);
      if (!index_type.IsIntegral() || !index_type.IsScalar()) return;
      if (webgl::IsConstantExpression(model, *index->index, constant_rules)) return;
      const double last = size - 1;
      // Past the int range the arithmetic would wrap: that range is not known.
      auto outside = [&](const Range& r) {
        return r.Finite() && r.lo <= r.hi && r.lo >= -2147483648.0 && r.hi <= 4294967295.0 &&
               (r.lo < 0.0 || r.hi > last);
      };
      if (!outside(ranges.Of(index->index))) return;
      // Only now the guards around the index, which are slower to find.
      const Overrides narrowed = guards.At(*index);
      ranges.SetOverrides(&narrowed);
      const Range range = ranges.Of(index->index);
      ranges.SetOverrides(nullptr);
      if (!outside(range)) return;
      Report(context, *index, base, size, noun, range, written.contains(index->id));
    });
  }

 private:
  static void Report(rule::RuleContext& context, const glsl::IndexExpr& index,
                     const glsl::Type& base, int size, const std::string& noun, const Range& range,
                     bool write) {
    const std::string index_text = Quoted(context, *index.index);
    const std::string base_text = Quoted(context, *index.base);
    const std::string type = context.Model().Spell(base);
    const std::string shown = base_text.empty() ? type : base_text;
    std::string instead;
    if (range.lo < 0.0) instead = shown + "[0]";
    if (range.hi > size - 1) {
      instead += (instead.empty() ? "" : " or ") + shown + "[" + std::to_string(size - 1) + "]";
    }
    std::string message = (index_text.empty() ? "the index" : "index '" + index_text + "'");
    message += " runs " + Number(range.lo) + ".." + Number(range.hi) + " here but ";
    message += base_text.empty() ? "the " + type : "'" + base_text + "' (" + type + ")";
    message += " has " + std::to_string(size) + " " + noun + ": browsers clamp it to 0.." +
               std::to_string(size - 1) + " (" + instead + " is " + (write ? "written" : "read") +
               " instead), native targets " + (write ? "write" : "read") + " out of bounds";
    context.Report(MakeDiagnostic(Severity::kWarning, std::string(kId), index.index->range,
                                  std::move(message)));
  }
};

}  // namespace

const rule::Rule& PortabilityIndexRangeRule() {
  static const IndexRangeRule rule;
  return rule;
}

}  // namespace shaderport::rules
