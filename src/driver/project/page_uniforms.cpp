#include "driver/project/page_uniforms.h"

#include <nlohmann/json.hpp>

#include "model/shipped_dialects.h"

namespace shaderport::driver::project {

std::string ShaderToyUniformsScript() {
  const model::HarnessDialect& site = model::ShaderToyDialect();
  nlohmann::ordered_json uniforms = nlohmann::ordered_json::array();
  for (const model::ProvidedVariable* uniform : model::ShaderToySiteUniforms()) {
    uniforms.push_back(uniform->name);
  }
  nlohmann::ordered_json entry_points = nlohmann::ordered_json::object();
  for (const model::EntryPoint& entry : site.entry_points) {
    nlohmann::ordered_json names = nlohmann::ordered_json::array();
    for (const model::ProvidedVariable& variable : entry.provides) names.push_back(variable.name);
    entry_points[entry.function] = std::move(names);
  }
  return "// The site's uniforms, from rules/dialects/shadertoy.toml.\n"
         "const spSiteUniforms = " +
         uniforms.dump() + ";\nconst spEntryPointUniforms = " + entry_points.dump() + ";\n";
}

}  // namespace shaderport::driver::project
