#include "model/shipped_dialects.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "model/embedded_dialects.h"

namespace shaderport::model {
namespace {

std::vector<HarnessDialect> LoadShipped() {
  std::vector<HarnessDialect> dialects;
  for (const EmbeddedTextFile& shipped : EmbeddedDialectFiles()) {
    DialectParse parsed = ParseDialect(shipped.text, "rules/dialects/" + std::string(shipped.name));
    if (parsed.dialect) dialects.push_back(std::move(*parsed.dialect));
  }
  std::sort(dialects.begin(), dialects.end(),
            [](const auto& a, const auto& b) { return a.name < b.name; });
  return dialects;
}

}  // namespace

std::span<const HarnessDialect> BuiltinDialects() {
  static const std::vector<HarnessDialect> dialects = LoadShipped();
  return dialects;
}

const HarnessDialect* FindBuiltinDialect(std::string_view name) {
  for (const HarnessDialect& dialect : BuiltinDialects()) {
    if (dialect.NameMatches(name)) return &dialect;
  }
  return nullptr;
}

const HarnessDialect& ShaderToyDialect() {
  static const HarnessDialect* const shadertoy = [] {
    const HarnessDialect* found = FindBuiltinDialect("shadertoy");
    if (found == nullptr) {
      // Compiled-in data, not user input: only a broken build gets here.
      std::fputs("shaderport: rules/dialects/shadertoy.toml is missing or invalid\n", stderr);
      std::abort();
    }
    return found;
  }();
  return *shadertoy;
}

std::vector<const ProvidedVariable*> ShaderToySiteUniforms() {
  std::vector<const ProvidedVariable*> uniforms;
  for (const ProvidedVariable& variable : ShaderToyDialect().provides) {
    if (variable.storage == ProvidedStorage::kUniform && variable.channel < 0) {
      uniforms.push_back(&variable);
    }
  }
  return uniforms;
}

}  // namespace shaderport::model
