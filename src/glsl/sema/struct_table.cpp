#include "glsl/sema/struct_table.h"

namespace shaderport::glsl {

StructTable::StructTable() {
  Add({"gl_DepthRangeParameters",
       {{"near", Type::Float()}, {"far", Type::Float()}, {"diff", Type::Float()}},
       kNoNode});
}

uint32_t StructTable::Add(StructInfo info) {
  structs_.push_back(std::move(info));
  return static_cast<uint32_t>(structs_.size() - 1);
}

std::optional<Type> StructTable::FieldType(uint32_t id, std::string_view field) const {
  if (id >= structs_.size()) return std::nullopt;
  for (const StructField& f : structs_[id].fields) {
    if (f.name == field) return f.type;
  }
  return std::nullopt;
}

}  // namespace shaderport::glsl
