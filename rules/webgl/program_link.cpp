#include "rules/webgl/program_link.h"

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace shaderport::rules {
namespace {

enum class Role { kVarying, kUniform, kOther };

struct Global {
  std::string name;
  Role role = Role::kOther;
  glsl::Type type;
  std::string type_name;  // spelled, so that struct types compare across stages
  glsl::Precision precision = glsl::Precision::kNone;
  bool invariant = false;
  bool used = false;
  SourceRange where;
  std::string members;  // struct types: every member's name, type and precision, nested
};

struct StageInterface {
  std::map<std::string, Global> globals;
  std::map<std::string, std::vector<Global>> blocks;  // uniform block name -> members
  bool invariant_all = false;                         // #pragma STDGL invariant(all)
  std::map<std::string, bool> builtin_invariant;      // `invariant gl_Position;`
  std::map<std::string, std::string> struct_members;  // struct name -> Global::members
};

bool HasPrecision(const glsl::Type& type) {
  const glsl::BaseType base = type.base;
  return base == glsl::BaseType::kFloat || base == glsl::BaseType::kInt ||
         base == glsl::BaseType::kUint || base == glsl::BaseType::kSampler;
}

// Default precisions in force, as `precision` statements set them in order.
class Defaults {
 public:
  explicit Defaults(bool vertex) {
    if (vertex) float_ = glsl::Precision::kHigh;
    int_ = vertex ? glsl::Precision::kHigh : glsl::Precision::kMedium;
  }
  void Apply(const glsl::PrecisionDeclaration& declaration) {
    if (declaration.type == nullptr) return;
    const std::string& name = declaration.type->name.text;
    if (name == "float") float_ = declaration.precision;
    if (name == "int") int_ = declaration.precision;
  }
  glsl::Precision For(const glsl::Type& type) const {
    if (type.base == glsl::BaseType::kFloat) return float_;
    if (type.base == glsl::BaseType::kInt || type.base == glsl::BaseType::kUint) return int_;
    if (type.base == glsl::BaseType::kSampler) return glsl::Precision::kLow;
    return glsl::Precision::kNone;
  }

 private:
  glsl::Precision float_ = glsl::Precision::kNone;
  glsl::Precision int_ = glsl::Precision::kNone;
};

glsl::Precision Effective(const glsl::TypeSpecifier* type, const glsl::Type& resolved,
                          const Defaults& defaults) {
  if (!HasPrecision(resolved)) return glsl::Precision::kNone;
  if (type != nullptr && type->precision != glsl::Precision::kNone) return type->precision;
  return defaults.For(resolved);
}

Role RoleOf(const glsl::QualifierList& qualifiers, bool vertex) {
  if (qualifiers.Has(glsl::QualifierKind::kUniform)) return Role::kUniform;
  if (qualifiers.Has(glsl::QualifierKind::kVarying)) return Role::kVarying;
  if (vertex && qualifiers.Has(glsl::QualifierKind::kOut)) return Role::kVarying;
  if (!vertex && qualifiers.Has(glsl::QualifierKind::kIn)) return Role::kVarying;
  return Role::kOther;
}

// `name type precision;` for each member of `specifier`, a nested struct's members in
// braces after its name: two stages' structs of one name must agree on all of it.
std::string MembersOf(const glsl::StructSpecifier& specifier, const Defaults& defaults,
                      const StageInterface& known) {
  std::string members;
  for (const glsl::VariableDeclaration* field : specifier.fields) {
    for (const glsl::Declarator* declarator : field->declarators) {
      // Fields are not symbols: a built-in type is read from its name (a struct has no
      // precision of its own).
      const std::optional<glsl::Type> builtin =
          field->type != nullptr && field->type->name_kind == glsl::TypeNameKind::kBuiltin
              ? glsl::BuiltinTypeByName(field->type->name.text)
              : std::nullopt;
      const glsl::Type type = builtin.value_or(glsl::Type::Unknown());
      std::string dimensions;
      for (const glsl::ArrayDimension& dimension : declarator->array) {
        const auto* literal =
            dimension.size != nullptr ? dimension.size->As<glsl::LiteralExpr>() : nullptr;
        dimensions += "[" + (literal != nullptr ? std::to_string(literal->int_value) : "?") + "]";
      }
      std::string spelled = field->type != nullptr ? field->type->name.text : "";
      if (const auto nested = known.struct_members.find(spelled);
          nested != known.struct_members.end()) {
        spelled += "{" + nested->second + "}";
      }
      members.append(declarator->name.text).append(" ").append(spelled).append(dimensions);
      members.append(" ").append(glsl::PrecisionSpelling(Effective(field->type, type, defaults)));
      members += ";";
    }
  }
  return members;
}

StageInterface Collect(const LinkStage& stage, bool vertex) {
  StageInterface result;
  for (const glsl::PragmaDirective& pragma : stage.preprocessed->pragmas) {
    if (pragma.text.starts_with("STDGL invariant ( all")) result.invariant_all = true;
  }
  Defaults defaults(vertex);
  const glsl::SemanticModel& model = *stage.model;
  for (const glsl::Node* node : stage.tree->Root()->declarations) {
    if (const auto* precision = node->As<glsl::PrecisionDeclaration>()) {
      defaults.Apply(*precision);
    } else if (const auto* variable = node->As<glsl::VariableDeclaration>()) {
      const Role role = RoleOf(variable->qualifiers, vertex);
      if (variable->type != nullptr && variable->type->struct_def != nullptr &&
          !variable->type->struct_def->name.Empty()) {
        result.struct_members[variable->type->struct_def->name.text] =
            MembersOf(*variable->type->struct_def, defaults, result);
      }
      for (const glsl::Declarator* declarator : variable->declarators) {
        const uint32_t symbol = model.SymbolAt(declarator->id);
        if (symbol == glsl::kNoSymbol || declarator->name.Empty()) continue;
        Global global;
        global.name = declarator->name.text;
        global.role = role;
        global.type = model.symbols[symbol].type;
        global.type_name = model.Spell(global.type);
        global.precision = Effective(variable->type, global.type, defaults);
        global.invariant = variable->qualifiers.Has(glsl::QualifierKind::kInvariant);
        global.used = !model.UsesOf(symbol).empty();
        global.where = declarator->name.range;
        if (variable->type != nullptr) {
          const auto members = result.struct_members.find(variable->type->name.text);
          if (members != result.struct_members.end()) global.members = members->second;
        }
        result.globals[global.name] = global;
      }
    } else if (const auto* qualifiers = node->As<glsl::QualifierDeclaration>()) {
      if (!qualifiers->qualifiers.Has(glsl::QualifierKind::kInvariant)) continue;
      for (const glsl::Name& name : qualifiers->names) {
        auto it = result.globals.find(name.text);
        if (it != result.globals.end()) it->second.invariant = true;
        if (name.text.starts_with("gl_")) result.builtin_invariant[name.text] = true;
      }
    } else if (const auto* block = node->As<glsl::InterfaceBlock>()) {
      if (!block->qualifiers.Has(glsl::QualifierKind::kUniform)) continue;
      std::vector<Global>& members = result.blocks[block->block_name.text];
      for (const glsl::VariableDeclaration* member : block->members) {
        for (const glsl::Declarator* declarator : member->declarators) {
          Global global;
          global.name = declarator->name.text;
          const std::optional<glsl::Type> type =
              member->type != nullptr && member->type->name_kind == glsl::TypeNameKind::kBuiltin
                  ? glsl::BuiltinTypeByName(member->type->name.text)
                  : std::nullopt;
          global.type = type.value_or(glsl::Type::Unknown());
          global.type_name = member->type != nullptr ? member->type->name.text : "";
          global.precision = Effective(member->type, global.type, defaults);
          global.where = declarator->name.range;
          members.push_back(global);
        }
      }
    }
  }
  // An ES 1.00 vertex shader's `#pragma STDGL invariant(all)` makes its outputs invariant.
  if (vertex && result.invariant_all) {
    for (auto& [name, global] : result.globals) {
      if (global.role == Role::kVarying) global.invariant = true;
    }
    result.builtin_invariant["gl_Position"] = result.builtin_invariant["gl_PointSize"] = true;
  }
  return result;
}

Diagnostic LinkError(std::string_view rule_id, const SourceRange& where, std::string message,
                     const SourceRange& other, std::string other_note) {
  Diagnostic diagnostic =
      MakeDiagnostic(Severity::kError, std::string(rule_id), where, std::move(message));
  if (other.Valid()) diagnostic.notes.push_back({other, std::move(other_note)});
  return diagnostic;
}

// One varying's footprint in the packing grid (GLSL ES 1.00 Appendix A.7).
struct Footprint {
  int rows = 0;
  int columns = 0;
  std::string name;
  SourceRange where;
};

Footprint FootprintOf(const Global& varying) {
  const glsl::Type element = varying.type.Element();
  int rows = 1;
  int columns = element.rows;
  if (element.columns > 1) {
    // mat2 takes two whole rows in Chromium, mat3 three rows of three, mat4 four of four.
    rows = element.columns;
    columns = element.columns == 2 ? 4 : element.rows;
  }
  const int count = varying.type.IsArray() ? std::max(1, varying.type.array_size) : 1;
  return {rows * count, columns, varying.name, varying.where};
}

// First-fit packing, widest then tallest first; returns the first that does not fit.
const Footprint* Pack(std::vector<Footprint>& varyings, int max_rows) {
  std::stable_sort(varyings.begin(), varyings.end(), [](const Footprint& a, const Footprint& b) {
    return a.columns != b.columns ? a.columns > b.columns : a.rows > b.rows;
  });
  std::vector<std::array<bool, 4>> grid(static_cast<size_t>(max_rows),
                                        {false, false, false, false});
  for (const Footprint& varying : varyings) {
    bool placed = false;
    for (int column = 0; column + varying.columns <= 4 && !placed; ++column) {
      for (int row = 0; row + varying.rows <= max_rows && !placed; ++row) {
        bool free = true;
        for (int r = row; r < row + varying.rows && free; ++r) {
          for (int c = column; c < column + varying.columns && free; ++c) {
            free = !grid[static_cast<size_t>(r)][static_cast<size_t>(c)];
          }
        }
        if (!free) continue;
        for (int r = row; r < row + varying.rows; ++r) {
          for (int c = column; c < column + varying.columns; ++c) {
            grid[static_cast<size_t>(r)][static_cast<size_t>(c)] = true;
          }
        }
        placed = true;
      }
    }
    if (!placed) return &varying;
  }
  return nullptr;
}

// The vectors a uniform takes in Chromium's count (ANGLE's register count, no packing):
// one per scalar or vector, one per matrix column, each member of a struct, times the
// array size.
int64_t UniformVectors(const glsl::Type& type, const glsl::SemanticModel& model, int depth = 0) {
  if (depth > 16) return 0;
  const int64_t count = type.IsArray() ? std::max(1, type.array_size) : 1;
  const glsl::Type element = type.Element();
  if (element.base == glsl::BaseType::kSampler) return 0;
  if (element.base == glsl::BaseType::kStruct) {
    int64_t members = 0;
    if (element.struct_id < model.structs.Size()) {
      for (const glsl::StructField& field : model.structs.Get(element.struct_id).fields) {
        members += UniformVectors(field.type, model, depth + 1);
      }
    }
    return count * members;
  }
  return count * element.columns;
}

// The first used uniform with which the stage's count passes `limit`, if any.
std::optional<std::pair<const Global*, int64_t>> UniformOverflow(const StageInterface& stage,
                                                                 const glsl::SemanticModel& model,
                                                                 int limit) {
  int64_t vectors = 0;
  std::vector<const Global*> uniforms;
  for (const auto& [name, global] : stage.globals) {
    if (global.role == Role::kUniform && global.used) uniforms.push_back(&global);
  }
  std::sort(uniforms.begin(), uniforms.end(),
            [](const Global* a, const Global* b) { return a->where.begin < b->where.begin; });
  for (const Global* uniform : uniforms) {
    vectors += UniformVectors(uniform->type, model);
    if (vectors > limit) return std::make_pair(uniform, vectors);
  }
  return std::nullopt;
}

}  // namespace

DiagnosticList CheckProgramLink(const LinkStage& vertex, const LinkStage& fragment,
                                const LinkLimits& limits) {
  DiagnosticList found;
  if (vertex.tree == nullptr || fragment.tree == nullptr || vertex.model == nullptr ||
      fragment.model == nullptr) {
    return found;
  }
  if ((vertex.version >= 300) != (fragment.version >= 300)) {
    found.push_back(LinkError(
        "link/version", {},
        "the vertex shader is GLSL ES " + std::string(vertex.version >= 300 ? "3.00" : "1.00") +
            " and the fragment shader GLSL ES " +
            std::string(fragment.version >= 300 ? "3.00" : "1.00") +
            "; browsers link only stages of one version (\"Fragment shader version does not "
            "match other shader versions\")",
        {}, ""));
    return found;
  }
  const StageInterface vs = Collect(vertex, true);
  const StageInterface fs = Collect(fragment, false);
  const bool essl100 = vertex.version < 300 && fragment.version < 300;

  std::vector<Footprint> packed;
  for (const auto& [name, input] : fs.globals) {
    if (input.role == Role::kVarying) {
      const auto it = vs.globals.find(name);
      const Global* output =
          it != vs.globals.end() && it->second.role == Role::kVarying ? &it->second : nullptr;
      if (output == nullptr) {
        if (input.used) {
          found.push_back(LinkError(
              "link/varying", input.where,
              "fragment input '" + name + "' is used but the vertex shader does not write it", {},
              ""));
        }
        continue;
      }
      if (output->type_name != input.type_name ||
          output->type.array_size != input.type.array_size) {
        found.push_back(LinkError("link/varying", input.where,
                                  "varying '" + name + "' is " + input.type_name + " here but " +
                                      output->type_name + " in the vertex shader",
                                  output->where, "declared here in the vertex shader"));
        continue;
      }
      if (essl100 && output->invariant != input.invariant) {
        found.push_back(LinkError("link/invariant", input.where,
                                  "varying '" + name + "' is " +
                                      (input.invariant ? "invariant" : "not invariant") +
                                      " here but " + (output->invariant ? "invariant" : "not") +
                                      " in the vertex shader; GLSL ES 1.00 requires both to agree",
                                  output->where, "declared here in the vertex shader"));
      }
      if (input.used || output->used) packed.push_back(FootprintOf(*output));
    } else if (input.role == Role::kUniform) {
      const auto it = vs.globals.find(name);
      if (it == vs.globals.end() || it->second.role != Role::kUniform) continue;
      const Global& other = it->second;
      if (other.type_name != input.type_name || other.type.array_size != input.type.array_size) {
        found.push_back(LinkError("link/uniform", input.where,
                                  "uniform '" + name + "' is " + input.type_name + " here but " +
                                      other.type_name + " in the vertex shader",
                                  other.where, "declared here in the vertex shader"));
      } else if (other.members != input.members) {
        found.push_back(
            LinkError("link/uniform", input.where,
                      "uniform '" + name + "' is a struct " + input.type_name +
                          " whose members differ from the vertex shader's (names, order, types or "
                          "precisions)",
                      other.where, "declared here in the vertex shader"));
      } else if (other.precision != input.precision) {
        found.push_back(LinkError(
            "link/uniform", input.where,
            "uniform '" + name + "' is " + glsl::PrecisionSpelling(input.precision) + " here but " +
                glsl::PrecisionSpelling(other.precision) +
                " in the vertex shader; a uniform shared by both stages must have one precision",
            other.where, "declared here in the vertex shader"));
      }
    }
  }
  for (const auto& [block, members] : fs.blocks) {
    const auto it = vs.blocks.find(block);
    if (it == vs.blocks.end()) continue;
    const std::vector<Global>& other = it->second;
    for (size_t i = 0; i < members.size() && i < other.size(); ++i) {
      if (members[i].name != other[i].name || members[i].type_name != other[i].type_name ||
          members[i].precision != other[i].precision) {
        found.push_back(LinkError("link/uniform", members[i].where,
                                  "member '" + members[i].name + "' of uniform block '" + block +
                                      "' differs from the vertex shader's (name, type or "
                                      "precision)",
                                  other[i].where, "declared here in the vertex shader"));
        break;
      }
    }
  }
  if (essl100) {
    static constexpr std::pair<const char*, const char*> kPairs[] = {
        {"gl_FragCoord", "gl_Position"}, {"gl_PointCoord", "gl_PointSize"}};
    for (const auto& [input, output] : kPairs) {
      if (fs.builtin_invariant.contains(input) && !vs.builtin_invariant.contains(output)) {
        SourceRange where;
        for (const glsl::Node* node : fragment.tree->Root()->declarations) {
          if (const auto* q = node->As<glsl::QualifierDeclaration>()) {
            for (const glsl::Name& n : q->names) {
              if (n.text == input) where = n.range;
            }
          }
        }
        found.push_back(LinkError(
            "link/invariant", where,
            std::string(input) + " is invariant but the vertex shader's " + output + " is not", {},
            ""));
      }
    }
  }
  for (const auto& [stage, model, limit, which] :
       {std::tuple{&vs, vertex.model, limits.max_vertex_uniform_vectors, "vertex"},
        std::tuple{&fs, fragment.model, limits.max_fragment_uniform_vectors, "fragment"}}) {
    if (const auto overflow = UniformOverflow(*stage, *model, limit)) {
      found.push_back(LinkError(
          "link/uniform-vectors", overflow->first->where,
          "with uniform '" + overflow->first->name + "' the " + which + " shader's uniforms take " +
              std::to_string(overflow->second) + " vectors, more than the context's " +
              std::to_string(limit) + " (MAX_" +
              (std::string(which) == "vertex" ? "VERTEX" : "FRAGMENT") + "_UNIFORM_VECTORS)",
          {}, ""));
    }
  }
  if (const Footprint* overflow = Pack(packed, limits.max_varying_vectors)) {
    found.push_back(LinkError("link/varying-packing", overflow->where,
                              "varying '" + overflow->name +
                                  "' does not fit: the program's "
                                  "varyings need more than " +
                                  std::to_string(limits.max_varying_vectors) +
                                  " vectors when packed (GLSL ES 1.00 Appendix A.7)",
                              {}, ""));
  }
  return found;
}

}  // namespace shaderport::rules
