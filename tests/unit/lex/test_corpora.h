// Loads the shared shader corpora used by the lexer and preprocessor sweeps.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace shaderport::glsl::testing {

struct ConformanceStage {
  std::string id;  // case id + ":vertex" / ":fragment"
  std::string source;
  bool should_compile;  // expected success, or a default stage
  int context_version;  // 1: WebGL 1, 2: WebGL 2
};

struct ShaderToyPass {
  std::string id;      // shader id + ":" + pass name
  std::string common;  // the Common pass of the shader ("" when none)
  std::string code;
};

inline std::vector<ConformanceStage> LoadConformanceStages() {
  std::vector<ConformanceStage> out;
  std::ifstream in(std::string(SHADERPORT_SHARED_DIR) + "/conformance/webgl-cts.jsonl");
  std::string line;
  while (std::getline(in, line)) {
    const auto j = nlohmann::json::parse(line);
    const auto& expected = j["expected"];
    for (const char* stage : {"vertex", "fragment"}) {
      const bool vertex = stage[0] == 'v';
      const auto& success = expected[vertex ? "vShaderSuccess" : "fShaderSuccess"];
      const bool is_default = j.value(vertex ? "vIsDefault" : "fIsDefault", false);
      out.push_back({j["id"].get<std::string>() + ":" + stage, j[stage].get<std::string>(),
                     is_default || (success.is_boolean() && success.get<bool>()),
                     j["contextVersion"].get<int>()});
    }
  }
  return out;
}

inline std::vector<ShaderToyPass> LoadShaderToyPasses() {
  std::vector<ShaderToyPass> out;
  std::ifstream in(std::string(SHADERPORT_SHARED_DIR) + "/corpus-shadertoy/permissive.jsonl");
  std::string line;
  while (std::getline(in, line)) {
    const auto j = nlohmann::json::parse(line);
    std::string common;
    for (const auto& pass : j["passes"]) {
      if (pass["type"] == "common") common = pass["code"].get<std::string>();
    }
    for (const auto& pass : j["passes"]) {
      out.push_back({j["id"].get<std::string>() + ":" + pass["name"].get<std::string>(),
                     pass["type"] == "common" ? std::string() : common,
                     pass["code"].get<std::string>()});
    }
  }
  return out;
}

// Every regular file under /work/main/corpus (may be empty while it is being filled).
inline std::vector<std::filesystem::path> CorpusFiles() {
  std::vector<std::filesystem::path> out;
  const std::filesystem::path root = std::string(SHADERPORT_SOURCE_DIR) + "/corpus";
  std::error_code ec;
  if (!std::filesystem::is_directory(root, ec)) return out;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root, ec)) {
    if (entry.is_regular_file()) out.push_back(entry.path());
  }
  return out;
}

inline std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace shaderport::glsl::testing
