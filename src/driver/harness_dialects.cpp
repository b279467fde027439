#include "driver/harness_dialects.h"

#include "model/shipped_dialects.h"

namespace shaderport::driver {

std::vector<std::string> ShippedHarnessDialectNames() {
  std::vector<std::string> names;
  for (const model::HarnessDialect& dialect : model::BuiltinDialects()) {
    for (const std::string& name : dialect.aliases) names.push_back(name);
    names.push_back(dialect.name);
  }
  return names;
}

rule::DialectLoadResult LoadHarnessDialect(std::string_view name_or_path, SourceManager& sources) {
  return rule::LoadDialect(name_or_path, sources);
}

}  // namespace shaderport::driver
