#include "glsl/sema/builtins.h"

#include <cctype>
#include <optional>
#include <unordered_map>

#include "glsl/sema/struct_table.h"

namespace shaderport::glsl {
namespace {

// Short names the .def rows use.
constexpr uint8_t E100 = kVersion100;
constexpr uint8_t E300 = kVersion300;
constexpr uint8_t ALL = kAllVersions;
constexpr uint8_t ANY = kAllStages;
constexpr uint8_t VERT = kVertexStage;
constexpr uint8_t FRAG = kFragmentStage;
constexpr BuiltinStorage IN = BuiltinStorage::kIn;
constexpr BuiltinStorage OUT = BuiltinStorage::kOut;
constexpr BuiltinStorage UNIFORM = BuiltinStorage::kUniform;
constexpr BuiltinStorage CONST = BuiltinStorage::kConst;

struct FunctionRow {
  uint8_t versions;
  uint8_t stages;
  std::string_view extension;
  std::string_view signature;
};

constexpr FunctionRow kFunctionRows[] = {
#define FN(versions, stages, extension, signature) {versions, stages, extension, signature},
#include "glsl/sema/builtin_functions.def"
#undef FN
};

struct VariableRow {
  uint8_t versions;
  uint8_t stages;
  std::string_view extension;
  BuiltinStorage storage;
  std::string_view declaration;
  int value;
};

constexpr VariableRow kVariableRows[] = {
#define VAR(versions, stages, extension, storage, declaration, value) \
  {versions, stages, extension, storage, declaration, value},
#include "glsl/sema/builtin_variables.def"
#undef VAR
};

std::vector<std::string_view> SplitWords(std::string_view text) {
  std::vector<std::string_view> words;
  size_t i = 0;
  while (i < text.size()) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    if (std::isspace(c)) {
      ++i;
    } else if (std::isalnum(c) || c == '_') {
      size_t start = i;
      while (i < text.size() &&
             (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_')) {
        ++i;
      }
      words.push_back(text.substr(start, i - start));
    } else {
      words.push_back(text.substr(i, 1));
      ++i;
    }
  }
  return words;
}

// One member of every family a row uses.
struct FamilyChoice {
  int size = 1;                       // genType / vec families
  BaseType texel = BaseType::kFloat;  // g-prefixed families
  int columns = 2;                    // mat / matNxM
  int rows = 2;
};

std::optional<Type> ResolveWord(std::string_view word, const FamilyChoice& c) {
  if (word == "genType") return Type::Vector(BaseType::kFloat, c.size);
  if (word == "genIType") return Type::Vector(BaseType::kInt, c.size);
  if (word == "genUType") return Type::Vector(BaseType::kUint, c.size);
  if (word == "genBType") return Type::Vector(BaseType::kBool, c.size);
  if (word == "vec") return Type::Vector(BaseType::kFloat, c.size);
  if (word == "ivec") return Type::Vector(BaseType::kInt, c.size);
  if (word == "uvec") return Type::Vector(BaseType::kUint, c.size);
  if (word == "bvec") return Type::Vector(BaseType::kBool, c.size);
  if (word == "mat" || word == "matNxM") return Type::Matrix(c.columns, c.rows);
  if (word == "gvec4") return Type::Vector(c.texel, 4);
  if (word == "gsampler2D") return Type::Sampler(SamplerDim::k2D, c.texel);
  if (word == "gsampler3D") return Type::Sampler(SamplerDim::k3D, c.texel);
  if (word == "gsamplerCube") return Type::Sampler(SamplerDim::kCube, c.texel);
  if (word == "gsampler2DArray") return Type::Sampler(SamplerDim::k2DArray, c.texel);
  if (word == "gl_DepthRangeParameters") {
    return Type::Struct(StructTable::kDepthRangeParameters);
  }
  return BuiltinTypeByName(word);
}

// All family members a signature expands to.
std::vector<FamilyChoice> Choices(const std::vector<std::string_view>& words) {
  int min_size = 1, max_size = 1;
  bool texel = false, square = false, any_matrix = false;
  for (std::string_view w : words) {
    if (w.starts_with("gen") && w.ends_with("Type")) min_size = 1, max_size = 4;
    if (w == "vec" || w == "ivec" || w == "uvec" || w == "bvec") min_size = 2, max_size = 4;
    if (w.size() > 1 && w[0] == 'g' && (w.starts_with("gvec") || w.starts_with("gsampler"))) {
      texel = true;
    }
    if (w == "mat") square = true;
    if (w == "matNxM") any_matrix = true;
  }
  std::vector<FamilyChoice> out;
  for (int size = min_size; size <= max_size; ++size) {
    for (BaseType t : {BaseType::kFloat, BaseType::kInt, BaseType::kUint}) {
      if (!texel && t != BaseType::kFloat) continue;
      for (int columns = 2; columns <= 4; ++columns) {
        for (int rows = 2; rows <= 4; ++rows) {
          bool wanted = any_matrix || (square && rows == columns) ||
                        (!square && !any_matrix && rows == 2 && columns == 2);
          if (wanted) out.push_back({size, t, columns, rows});
        }
      }
    }
  }
  return out;
}

// Parses one signature for one family member; false on a malformed row.
bool ParseSignature(const std::vector<std::string_view>& words, const FamilyChoice& choice,
                    BuiltinFunction& plain, std::optional<BuiltinParam>& bias) {
  size_t i = 0;
  auto next = [&]() -> std::string_view { return i < words.size() ? words[i++] : ""; };
  std::optional<Type> ret = ResolveWord(next(), choice);
  if (!ret) return false;
  plain.return_type = *ret;
  plain.name = std::string(next());
  if (next() != "(") return false;
  BuiltinParam param;
  bool optional = false;
  while (i < words.size()) {
    std::string_view w = next();
    if (w == ")") return !optional;
    if (w == "," || w == "]") continue;
    if (w == "[") {
      optional = true;
    } else if (w == "out") {
      param.qualifier = ParamQualifier::kOut;
    } else if (w == "inout") {
      param.qualifier = ParamQualifier::kInOut;
    } else if (w == "const") {
      param.must_be_constant = true;
    } else if (std::optional<Type> t = ResolveWord(w, choice)) {
      param.type = *t;
      if (i < words.size() && words[i] != "," && words[i] != ")" && words[i] != "[") ++i;  // name
      if (optional) {
        bias = param;
        optional = false;
      } else {
        plain.params.push_back(param);
      }
      param = {};
    } else {
      return false;
    }
  }
  return false;
}

struct Tables {
  std::vector<BuiltinFunction> functions;
  std::vector<BuiltinVariable> variables;
  std::unordered_map<std::string_view, std::vector<uint32_t>> by_name;
  // The same overloads as pointers, for lookups that must not allocate.
  std::unordered_map<std::string_view, std::vector<const BuiltinFunction*>> overloads;
};

const Tables& GetTables() {
  static const Tables tables = [] {
    Tables t;
    for (uint32_t row = 0; row < std::size(kFunctionRows); ++row) {
      const FunctionRow& r = kFunctionRows[row];
      std::vector<std::string_view> words = SplitWords(r.signature);
      for (const FamilyChoice& choice : Choices(words)) {
        BuiltinFunction f;
        std::optional<BuiltinParam> bias;
        if (!ParseSignature(words, choice, f, bias)) continue;  // the table test catches this
        f.versions = r.versions;
        f.stages = r.stages;
        f.extension = r.extension;
        f.row = row;
        t.functions.push_back(f);
        if (bias) {
          f.params.push_back(*bias);
          f.stages = r.stages & FRAG;
          t.functions.push_back(std::move(f));
        }
      }
    }
    for (const VariableRow& r : kVariableRows) {
      std::vector<std::string_view> words = SplitWords(r.declaration);
      std::optional<Type> type = ResolveWord(words.front(), FamilyChoice{});
      if (!type) continue;
      if (words.size() == 4 && words[1] == "[") *type = type->ArrayOf(Type::kUnsizedArray);
      t.variables.push_back({std::string(words.back()), *type, r.storage, r.versions, r.stages,
                             r.extension, r.value});
    }
    for (uint32_t i = 0; i < t.functions.size(); ++i) {
      t.by_name[t.functions[i].name].push_back(i);
      t.overloads[t.functions[i].name].push_back(&t.functions[i]);
    }
    return t;
  }();
  return tables;
}

}  // namespace

size_t BuiltinFunctionRowCount() { return std::size(kFunctionRows); }
size_t BuiltinVariableRowCount() { return std::size(kVariableRows); }

std::span<const BuiltinFunction> AllBuiltinFunctions() { return GetTables().functions; }
std::span<const BuiltinVariable> AllBuiltinVariables() { return GetTables().variables; }

std::vector<const BuiltinFunction*> BuiltinOverloads(std::string_view name) {
  const Tables& t = GetTables();
  std::vector<const BuiltinFunction*> out;
  auto it = t.by_name.find(name);
  if (it == t.by_name.end()) return out;
  for (uint32_t i : it->second) out.push_back(&t.functions[i]);
  return out;
}

std::span<const BuiltinFunction* const> BuiltinOverloadList(std::string_view name) {
  const Tables& t = GetTables();
  auto it = t.overloads.find(name);
  if (it == t.overloads.end()) return {};
  return it->second;
}

const BuiltinVariable* FindBuiltinVariable(std::string_view name, int version, model::Stage stage) {
  for (const BuiltinVariable& v : GetTables().variables) {
    if (v.name == name && v.AvailableIn(version, stage)) return &v;
  }
  return nullptr;
}

bool IsBuiltinFunctionName(std::string_view name) { return GetTables().by_name.contains(name); }

}  // namespace shaderport::glsl
