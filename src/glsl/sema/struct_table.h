// The struct types known to one analysis, by id. Id 0 is always the built-in
// gl_DepthRangeParameters, so that gl_DepthRange can be typed without a shader.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glsl/sema/type.h"

namespace shaderport::glsl {

inline constexpr uint32_t kNoNode = UINT32_MAX;

struct StructField {
  std::string name;
  Type type;
};

struct StructInfo {
  std::string name;  // empty for an anonymous struct (`struct { float a; } s;`)
  std::vector<StructField> fields;
  uint32_t declaration = kNoNode;  // syntax node id of the declaration, if any
};

class StructTable {
 public:
  static constexpr uint32_t kDepthRangeParameters = 0;

  StructTable();

  uint32_t Add(StructInfo info);
  const StructInfo& Get(uint32_t id) const { return structs_.at(id); }
  size_t Size() const { return structs_.size(); }
  // The type of `field` in struct `id`, or nothing when there is no such field.
  std::optional<Type> FieldType(uint32_t id, std::string_view field) const;

 private:
  std::vector<StructInfo> structs_;
};

}  // namespace shaderport::glsl
