#include "toolchain/reflect.h"

#include <algorithm>
#include <exception>
#include <nlohmann/json.hpp>
#include <spirv_cross.hpp>
#include <string_view>
#include <unordered_set>

#include "model/shipped_dialects.h"
#include "toolchain/sampler_usage.h"

namespace shaderport::toolchain {
namespace {

using nlohmann::ordered_json;
using spirv_cross::SPIRType;

// Exposes the plain (non-opaque, non-block) uniforms that ShaderResources does not list.
class ReflectCompiler : public spirv_cross::Compiler {
 public:
  using Compiler::Compiler;
  std::vector<spirv_cross::VariableID> PlainUniforms() const {
    std::vector<spirv_cross::VariableID> ids;
    ir.for_each_typed_id<spirv_cross::SPIRVariable>([&](uint32_t id,
                                                        const spirv_cross::SPIRVariable& variable) {
      if (variable.storage != spv::StorageClassUniformConstant) return;
      const SPIRType::BaseType base = get_type(variable.basetype).basetype;
      if (base == SPIRType::SampledImage || base == SPIRType::Image || base == SPIRType::Sampler) {
        return;
      }
      ids.push_back(id);
    });
    return ids;
  }
};

std::string ScalarPrefix(SPIRType::BaseType base) {
  switch (base) {
    case SPIRType::Boolean:
      return "b";
    case SPIRType::Int:
      return "i";
    case SPIRType::UInt:
      return "u";
    default:
      return "";
  }
}

std::string ScalarName(SPIRType::BaseType base) {
  switch (base) {
    case SPIRType::Boolean:
      return "bool";
    case SPIRType::Int:
      return "int";
    case SPIRType::UInt:
      return "uint";
    case SPIRType::Float:
      return "float";
    default:
      return "unknown";
  }
}

// "2D", "3D", "Cube", "2DArray", with "Shadow" for depth comparison samplers.
std::string SamplerKind(const SPIRType& type) {
  std::string kind;
  switch (type.image.dim) {
    case spv::Dim2D:
      kind = "2D";
      break;
    case spv::Dim3D:
      kind = "3D";
      break;
    case spv::DimCube:
      kind = "Cube";
      break;
    default:
      kind = "other";
      break;
  }
  if (type.image.arrayed) kind += "Array";
  if (type.image.depth) kind += "Shadow";
  return kind;
}

std::string ArraySuffix(const SPIRType& type) {
  std::string suffix;
  // SPIRV-Cross stores the outermost dimension last.
  for (size_t i = type.array.size(); i-- > 0;) {
    const bool literal = i < type.array_size_literal.size() && type.array_size_literal[i];
    suffix += literal ? "[" + std::to_string(type.array[i]) + "]" : "[]";
  }
  return suffix;
}

// The GLSL spelling of a type: "vec3", "mat4", "ivec2", "sampler2D", "float[4]", "Light".
std::string GlslTypeName(const spirv_cross::Compiler& compiler, const SPIRType& type) {
  std::string name;
  if (type.basetype == SPIRType::SampledImage || type.basetype == SPIRType::Image) {
    name =
        ScalarPrefix(compiler.get_type(type.image.type).basetype) + "sampler" + SamplerKind(type);
  } else if (type.basetype == SPIRType::Struct) {
    name = compiler.get_name(type.self);
    if (name.empty()) name = "struct";
  } else if (type.columns > 1) {
    name = "mat" + std::to_string(type.columns);
    if (type.columns != type.vecsize) name += "x" + std::to_string(type.vecsize);
  } else if (type.vecsize > 1) {
    name = ScalarPrefix(type.basetype) + "vec" + std::to_string(type.vecsize);
  } else {
    name = ScalarName(type.basetype);
  }
  return name + ArraySuffix(type);
}

std::string BuiltinName(spv::BuiltIn builtin) {
  switch (builtin) {
    case spv::BuiltInPosition:
      return "gl_Position";
    case spv::BuiltInPointSize:
      return "gl_PointSize";
    case spv::BuiltInVertexId:
    case spv::BuiltInVertexIndex:
      return "gl_VertexID";
    case spv::BuiltInInstanceId:
    case spv::BuiltInInstanceIndex:
      return "gl_InstanceID";
    case spv::BuiltInFragCoord:
      return "gl_FragCoord";
    case spv::BuiltInFrontFacing:
      return "gl_FrontFacing";
    case spv::BuiltInPointCoord:
      return "gl_PointCoord";
    case spv::BuiltInFragDepth:
      return "gl_FragDepth";
    default:
      return "builtin-" + std::to_string(static_cast<int>(builtin));
  }
}

// SPIR-V keeps no declaration order (glslang numbers ids by first use), so lists are sorted:
// by location where there is one, then by name.
ordered_json Sorted(ordered_json list) {
  std::stable_sort(list.begin(), list.end(), [](const ordered_json& a, const ordered_json& b) {
    const int64_t la = a.value("location", int64_t{-1});
    const int64_t lb = b.value("location", int64_t{-1});
    if (la != lb) return la < lb;
    return a["name"].get<std::string>() < b["name"].get<std::string>();
  });
  return list;
}

struct Context {
  const ReflectCompiler& compiler;
  std::unordered_set<spirv_cross::VariableID> active;
  bool Used(spirv_cross::VariableID id) const { return active.count(id) != 0; }
};

ordered_json Variable(const Context& context, spirv_cross::VariableID id) {
  const ReflectCompiler& compiler = context.compiler;
  ordered_json entry;
  entry["name"] = compiler.get_name(id);
  entry["type"] = GlslTypeName(compiler, compiler.get_type_from_variable(id));
  entry["used"] = context.Used(id);
  return entry;
}

ordered_json Interface(const Context& context,
                       const spirv_cross::SmallVector<spirv_cross::Resource>& resources) {
  ordered_json list = ordered_json::array();
  for (const spirv_cross::Resource& resource : resources) {
    ordered_json entry = Variable(context, resource.id);
    if (context.compiler.has_decoration(resource.id, spv::DecorationLocation)) {
      entry["location"] = context.compiler.get_decoration(resource.id, spv::DecorationLocation);
    }
    list.push_back(std::move(entry));
  }
  return list;
}

ordered_json Builtins(const ReflectCompiler& compiler,
                      const spirv_cross::SmallVector<spirv_cross::BuiltInResource>& builtins,
                      spv::StorageClass storage) {
  ordered_json list = ordered_json::array();
  for (const spirv_cross::BuiltInResource& builtin : builtins) {
    if (!compiler.has_active_builtin(builtin.builtin, storage)) continue;
    const std::string name = BuiltinName(builtin.builtin);
    if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
  }
  return list;
}

ordered_json UniformBlocks(const Context& context,
                           const spirv_cross::SmallVector<spirv_cross::Resource>& blocks) {
  const ReflectCompiler& compiler = context.compiler;
  ordered_json list = ordered_json::array();
  for (const spirv_cross::Resource& block : blocks) {
    const SPIRType& type = compiler.get_type(block.base_type_id);
    ordered_json entry;
    entry["name"] = compiler.get_name(block.id);  // instance name; "" when there is none
    entry["blockName"] = compiler.get_name(block.base_type_id);
    entry["used"] = context.Used(block.id);
    ordered_json members = ordered_json::array();
    for (uint32_t i = 0; i < type.member_types.size(); ++i) {
      members.push_back(
          {{"name", compiler.get_member_name(block.base_type_id, i)},
           {"type", GlslTypeName(compiler, compiler.get_type(type.member_types[i]))}});
    }
    entry["members"] = std::move(members);
    list.push_back(std::move(entry));
  }
  return list;
}

ordered_json Samplers(const Context& context,
                      const spirv_cross::SmallVector<spirv_cross::Resource>& samplers,
                      const std::map<std::string, std::set<std::string>>& operations) {
  ordered_json list = ordered_json::array();
  for (const spirv_cross::Resource& sampler : samplers) {
    ordered_json entry = Variable(context, sampler.id);
    entry["kind"] = SamplerKind(context.compiler.get_type(sampler.base_type_id));
    const auto it = operations.find(entry["name"].get<std::string>());
    entry["functions"] = it == operations.end() ? ordered_json::array() : ordered_json(it->second);
    list.push_back(std::move(entry));
  }
  return list;
}

// The site's uniforms and channels, as rules/dialects/shadertoy.toml lists them.
ordered_json ShaderToy(const ordered_json& uniforms, const ordered_json& samplers) {
  ordered_json channels = ordered_json::array();
  for (const model::ProvidedVariable& variable : model::ShaderToyDialect().provides) {
    if (variable.channel < 0) continue;
    ordered_json channel = {{"channel", variable.channel},
                            {"name", variable.name},
                            {"declared", false},
                            {"used", false},
                            {"kind", nullptr},
                            {"functions", ordered_json::array()}};
    for (const ordered_json& sampler : samplers) {
      if (sampler["name"] != variable.name) continue;
      channel["declared"] = true;
      channel["used"] = sampler["used"];
      channel["kind"] = sampler["kind"];
      channel["functions"] = sampler["functions"];
    }
    channels.push_back(std::move(channel));
  }
  // In the order the site declares them.
  ordered_json used = ordered_json::array();
  for (const model::ProvidedVariable* known : model::ShaderToySiteUniforms()) {
    for (const ordered_json& uniform : uniforms) {
      if (uniform["name"] == known->name && uniform["used"].get<bool>())
        used.push_back(known->name);
    }
  }
  return {{"channels", std::move(channels)}, {"uniformsUsed", std::move(used)}};
}

ordered_json BuildJson(const SpirvWords& words, model::Stage stage, bool shadertoy) {
  ReflectCompiler compiler(words);
  const auto active = compiler.get_active_interface_variables();
  Context context{compiler, {active.begin(), active.end()}};
  compiler.update_active_builtins();
  const spirv_cross::ShaderResources resources = compiler.get_shader_resources();

  ordered_json json;
  json["version"] = 1;
  json["stage"] = stage == model::Stage::kVertex ? "vertex" : "fragment";
  const auto entry_points = compiler.get_entry_points_and_stages();
  json["entryPoint"] = entry_points.empty() ? "main" : entry_points.front().name;
  ordered_json uniforms = ordered_json::array();
  for (const spirv_cross::VariableID id : compiler.PlainUniforms()) {
    uniforms.push_back(Variable(context, id));
  }
  uniforms = Sorted(std::move(uniforms));
  json["uniforms"] = uniforms;
  json["uniformBlocks"] = Sorted(UniformBlocks(context, resources.uniform_buffers));
  const ordered_json samplers =
      Sorted(Samplers(context, resources.sampled_images, SamplerOperations(InlineAllCalls(words))));
  json["samplers"] = samplers;
  json["inputs"] = Sorted(Interface(context, resources.stage_inputs));
  json["outputs"] = Sorted(Interface(context, resources.stage_outputs));
  json["builtinInputs"] = Builtins(compiler, resources.builtin_inputs, spv::StorageClassInput);
  json["builtinOutputs"] = Builtins(compiler, resources.builtin_outputs, spv::StorageClassOutput);
  if (shadertoy) json["shadertoy"] = ShaderToy(uniforms, samplers);
  return json;
}

}  // namespace

ReflectOutcome Reflect(const SpirvWords& words, model::Stage stage, bool shadertoy) {
  ReflectOutcome outcome;
  try {
    outcome.json = BuildJson(words, stage, shadertoy).dump(2) + "\n";
  } catch (const std::exception& e) {
    outcome.json.clear();
    outcome.error = e.what();
  }
  return outcome;
}

}  // namespace shaderport::toolchain
