#include "glsl/sema/type.h"

#include <array>

#include "glsl/sema/struct_table.h"

namespace shaderport::glsl {
namespace {

const char* ScalarName(BaseType base) {
  switch (base) {
    case BaseType::kVoid:
      return "void";
    case BaseType::kBool:
      return "bool";
    case BaseType::kInt:
      return "int";
    case BaseType::kUint:
      return "uint";
    case BaseType::kFloat:
      return "float";
    default:
      return "unknown";
  }
}

const char* VectorPrefix(BaseType base) {
  switch (base) {
    case BaseType::kBool:
      return "bvec";
    case BaseType::kInt:
      return "ivec";
    case BaseType::kUint:
      return "uvec";
    default:
      return "vec";
  }
}

const char* SamplerPrefix(BaseType sampled) {
  switch (sampled) {
    case BaseType::kInt:
      return "i";
    case BaseType::kUint:
      return "u";
    default:
      return "";
  }
}

const char* DimName(SamplerDim dim) {
  switch (dim) {
    case SamplerDim::k2D:
      return "2D";
    case SamplerDim::k3D:
      return "3D";
    case SamplerDim::kCube:
      return "Cube";
    case SamplerDim::k2DArray:
      return "2DArray";
    default:
      return "";
  }
}

std::string SpellElement(const Type& type, const StructTable* structs) {
  switch (type.base) {
    case BaseType::kSampler:
      return std::string(SamplerPrefix(type.sampled)) + "sampler" + DimName(type.sampler_dim) +
             (type.shadow ? "Shadow" : "");
    case BaseType::kStruct:
      if (structs != nullptr && type.struct_id < structs->Size() &&
          !structs->Get(type.struct_id).name.empty()) {
        return structs->Get(type.struct_id).name;
      }
      return "struct#" + std::to_string(type.struct_id);
    case BaseType::kBool:
    case BaseType::kInt:
    case BaseType::kUint:
    case BaseType::kFloat:
      if (type.columns > 1) {
        std::string name = "mat" + std::to_string(type.columns);
        if (type.rows != type.columns) name += "x" + std::to_string(type.rows);
        return name;
      }
      if (type.rows > 1) return VectorPrefix(type.base) + std::to_string(type.rows);
      return ScalarName(type.base);
    default:
      return ScalarName(type.base);
  }
}

struct NamedType {
  std::string_view name;
  Type type;
};

constexpr std::array kSamplers = {
    NamedType{"sampler2D", Type::Sampler(SamplerDim::k2D)},
    NamedType{"sampler3D", Type::Sampler(SamplerDim::k3D)},
    NamedType{"samplerCube", Type::Sampler(SamplerDim::kCube)},
    NamedType{"sampler2DArray", Type::Sampler(SamplerDim::k2DArray)},
    NamedType{"sampler2DShadow", Type::Sampler(SamplerDim::k2D, BaseType::kFloat, true)},
    NamedType{"samplerCubeShadow", Type::Sampler(SamplerDim::kCube, BaseType::kFloat, true)},
    NamedType{"sampler2DArrayShadow", Type::Sampler(SamplerDim::k2DArray, BaseType::kFloat, true)},
    NamedType{"isampler2D", Type::Sampler(SamplerDim::k2D, BaseType::kInt)},
    NamedType{"isampler3D", Type::Sampler(SamplerDim::k3D, BaseType::kInt)},
    NamedType{"isamplerCube", Type::Sampler(SamplerDim::kCube, BaseType::kInt)},
    NamedType{"isampler2DArray", Type::Sampler(SamplerDim::k2DArray, BaseType::kInt)},
    NamedType{"usampler2D", Type::Sampler(SamplerDim::k2D, BaseType::kUint)},
    NamedType{"usampler3D", Type::Sampler(SamplerDim::k3D, BaseType::kUint)},
    NamedType{"usamplerCube", Type::Sampler(SamplerDim::kCube, BaseType::kUint)},
    NamedType{"usampler2DArray", Type::Sampler(SamplerDim::k2DArray, BaseType::kUint)},
};

// `digits` is "2".."4": returns 2..4, else 0.
int SmallSize(std::string_view digits) {
  if (digits.size() != 1 || digits[0] < '2' || digits[0] > '4') return 0;
  return digits[0] - '0';
}

}  // namespace

std::string Spell(const Type& type, const StructTable* structs) {
  std::string name = SpellElement(type, structs);
  if (type.array_size == Type::kUnsizedArray) return name + "[]";
  if (type.array_size > 0) return name + "[" + std::to_string(type.array_size) + "]";
  return name;
}

std::optional<Type> BuiltinTypeByName(std::string_view name) {
  if (name == "void") return Type::Void();
  if (name == "bool") return Type::Bool();
  if (name == "int") return Type::Int();
  if (name == "uint") return Type::Uint();
  if (name == "float") return Type::Float();
  for (const NamedType& s : kSamplers) {
    if (s.name == name) return s.type;
  }
  struct Prefix {
    std::string_view text;
    BaseType base;
  };
  for (const Prefix& p : {Prefix{"bvec", BaseType::kBool}, Prefix{"ivec", BaseType::kInt},
                          Prefix{"uvec", BaseType::kUint}, Prefix{"vec", BaseType::kFloat}}) {
    if (name.starts_with(p.text)) {
      int size = SmallSize(name.substr(p.text.size()));
      if (size == 0) return std::nullopt;
      return Type::Vector(p.base, size);
    }
  }
  if (name.starts_with("mat")) {
    std::string_view rest = name.substr(3);
    if (rest.size() == 1) {
      int size = SmallSize(rest);
      if (size == 0) return std::nullopt;
      return Type::Matrix(size, size);
    }
    if (rest.size() == 3 && rest[1] == 'x') {
      int columns = SmallSize(rest.substr(0, 1));
      int rows = SmallSize(rest.substr(2, 1));
      if (columns == 0 || rows == 0) return std::nullopt;
      return Type::Matrix(columns, rows);
    }
  }
  return std::nullopt;
}

bool BuiltinTypeAvailable(const Type& type, int version) {
  if (version >= 300) return true;
  switch (type.base) {
    case BaseType::kUint:
      return false;
    case BaseType::kSampler:
      return !type.shadow && type.sampled == BaseType::kFloat &&
             (type.sampler_dim == SamplerDim::k2D || type.sampler_dim == SamplerDim::kCube);
    case BaseType::kFloat:
      return type.columns == 1 || type.columns == type.rows;
    default:
      return true;
  }
}

}  // namespace shaderport::glsl
