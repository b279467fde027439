// A non-constant index into a vector, a matrix or a sized array becomes
// `clamp(i, 0, N - 1)`, for reads and for writes, as ANGLE's ClampIndirectIndices
// does for WebGL: an out-of-range index then reads or writes the last element
// instead of undefined memory (a browser draws it; a native driver may not).
// GLSL ES 1.00 has no integer clamp(): there the clamp is done in float, as ANGLE does.
#include "glsl/sema/language.h"
#include "glsl/syntax/visit.h"
#include "glsl/webgl_semantics/semantics_context.h"

namespace shaderport::glsl {
namespace {

// Number of elements the index selects from; 0 when unknown or not clampable.
int32_t IndexedSize(const Type& type) {
  if (type.IsArray()) return type.array_size > 0 ? type.array_size : 0;
  if (type.IsMatrix()) return type.columns;
  if (type.IsVector()) return type.rows;
  return 0;
}

}  // namespace

void ClampIndirectIndices(SemanticsContext& c) {
  VisitPreorder(c.tree, [&](const Node& node, uint32_t) {
    const auto* index = node.As<IndexExpr>();
    if (index == nullptr || index->base == nullptr || index->index == nullptr) return true;
    if (IsConstantExpression(index->index, c.model)) return true;
    const int32_t size = IndexedSize(c.model.TypeOf(index->base->id));
    const Type& index_type = c.model.TypeOf(index->index->id);
    if (size <= 0 || !index_type.IsIntegral() || !index_type.IsScalar()) return true;
    const auto span = c.edits.Span(*index->index);
    if (!span) {
      ++c.result.skipped;
      return true;
    }
    const std::string last = std::to_string(size - 1);
    if (c.model.version < kEssl300) {
      c.edits.Insert(span->file, span->begin, "int(clamp(float(");
      c.edits.Insert(span->file, span->end, "), 0.0, " + last + ".0))");
    } else {
      const bool is_uint = index_type.base == BaseType::kUint;
      c.edits.Insert(span->file, span->begin, is_uint ? "clamp(int(" : "clamp((");
      c.edits.Insert(span->file, span->end, "), 0, " + last + ")");
    }
    ++c.result.clamped;
    return true;
  });
}

}  // namespace shaderport::glsl
