#include "model/harness_dialect.h"

namespace shaderport::model {

bool HarnessDialect::NameMatches(std::string_view name_or_alias) const {
  if (name == name_or_alias) return true;
  for (const std::string& alias : aliases) {
    if (alias == name_or_alias) return true;
  }
  return false;
}

int HarnessDialect::PreludeVersion() const {
  // The `#version` line of the prelude, words separated by blanks.
  const size_t at = prelude.find("#version");
  if (at == std::string::npos) return 0;
  const size_t end = prelude.find('\n', at);
  const std::string_view line =
      std::string_view(prelude).substr(at, end == std::string::npos ? std::string::npos : end - at);
  std::string words;
  for (char c : line) {
    if (c == ' ' || c == '\t' || c == '\r') {
      if (!words.empty() && words.back() != ' ') words += ' ';
    } else {
      words += c;
    }
  }
  while (!words.empty() && words.back() == ' ') words.pop_back();
  if (words == "#version 100") return 100;
  if (words == "#version 300 es") return 300;
  return 0;
}

const ProvidedVariable* HarnessDialect::FindProvided(std::string_view variable) const {
  for (const ProvidedVariable& provided : provides) {
    if (provided.name == variable) return &provided;
  }
  for (const EntryPoint& entry : entry_points) {
    for (const ProvidedVariable& provided : entry.provides) {
      if (provided.name == variable) return &provided;
    }
  }
  return nullptr;
}

const EntryPoint* HarnessDialect::FindEntryPoint(std::string_view function) const {
  for (const EntryPoint& entry : entry_points) {
    if (entry.function == function) return &entry;
  }
  return nullptr;
}

std::string_view StorageName(ProvidedStorage storage) {
  switch (storage) {
    case ProvidedStorage::kInput:
      return "in";
    case ProvidedStorage::kOutput:
      return "out";
    case ProvidedStorage::kUniform:
      break;
  }
  return "uniform";
}

std::string_view DefaultPrecision(std::string_view type) {
  const std::string_view base = type.substr(0, type.find('['));
  if (base == "sampler2D" || base == "samplerCube" || base.starts_with("bvec") || base == "bool") {
    return "";  // sampler2D and samplerCube default to lowp everywhere, as on the hosts
  }
  if (base.find("sampler") != std::string_view::npos) return "mediump";  // as ShaderToy's sampler3D
  return "highp";
}

std::string DeclarationOf(const ProvidedVariable& variable, std::string_view type_override,
                          PrecisionSpelling spelling) {
  const std::string_view type = type_override.empty() ? variable.type : type_override;
  // GLSL ES writes the array size after the name: `uniform float iChannelTime[4];`.
  const size_t bracket = type.find('[');
  const std::string_view base = type.substr(0, bracket);
  const std::string_view array = bracket == std::string_view::npos ? "" : type.substr(bracket);
  std::string text(StorageName(variable.storage));
  text += ' ';
  std::string_view precision = variable.precision;
  if (precision.empty() && spelling == PrecisionSpelling::kExplicit)
    precision = DefaultPrecision(type);
  if (!precision.empty()) {
    text += precision;
    text += ' ';
  }
  text += base;
  text += ' ';
  text += variable.name;
  text += array;
  text += ';';
  return text;
}

}  // namespace shaderport::model
