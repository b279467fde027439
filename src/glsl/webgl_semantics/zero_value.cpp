#include "glsl/webgl_semantics/zero_value.h"

#include "glsl/sema/language.h"

namespace shaderport::glsl {
namespace {

constexpr int kMaxStructDepth = 16;

const char* ScalarZero(BaseType base) {
  switch (base) {
    case BaseType::kFloat:
      return "0.0";
    case BaseType::kInt:
      return "0";
    case BaseType::kUint:
      return "0u";
    case BaseType::kBool:
      return "false";
    default:
      return nullptr;
  }
}

std::optional<std::string> ZeroOf(const Type& type, const StructTable& structs, int version,
                                  int depth) {
  if (depth > kMaxStructDepth) return std::nullopt;
  if (type.IsArray()) {
    if (version < kEssl300 || type.array_size <= 0 ||
        type.array_size > kMaxZeroConstructorElements) {
      return std::nullopt;
    }
    const Type element = type.Element();
    const auto zero = ZeroOf(element, structs, version, depth + 1);
    if (!zero) return std::nullopt;
    std::string text = Spell(element, &structs) + "[" + std::to_string(type.array_size) + "](";
    for (int32_t i = 0; i < type.array_size; ++i) {
      if (i > 0) text += ", ";
      text += *zero;
    }
    return text + ")";
  }
  if (type.IsStruct()) {
    if (type.struct_id >= structs.Size()) return std::nullopt;
    const StructInfo& info = structs.Get(type.struct_id);
    if (info.name.empty() || info.fields.empty()) return std::nullopt;
    std::string text = info.name + "(";
    for (size_t i = 0; i < info.fields.size(); ++i) {
      const auto zero = ZeroOf(info.fields[i].type, structs, version, depth + 1);
      if (!zero) return std::nullopt;
      if (i > 0) text += ", ";
      text += *zero;
    }
    return text + ")";
  }
  const char* scalar = ScalarZero(type.base);
  if (scalar == nullptr) return std::nullopt;
  if (type.IsScalar()) return std::string(scalar);
  // vecN(0.0), matCxR(0.0): a single scalar fills a vector and, for a matrix,
  // gives a diagonal of that scalar: all zero.
  return Spell(type, &structs) + "(" + scalar + ")";
}

}  // namespace

std::optional<std::string> ZeroValue(const Type& type, const StructTable& structs, int version) {
  return ZeroOf(type, structs, version, 0);
}

}  // namespace shaderport::glsl
