// The golden cases of one rule category: every input under tests/rules/<category>-<rule>/
// (`.frag`, `.vert` or `.glsl`, not the `.out.` fixed outputs), sorted by path.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace shaderport::testing {

struct GoldenCase {
  std::filesystem::path input;
  std::string rule_id;  // "<category>/<rule>", from the directory name
};

inline std::vector<GoldenCase> GoldenCases(std::string_view category) {
  namespace fs = std::filesystem;
  const std::string prefix = std::string(category) + "-";
  std::vector<GoldenCase> cases;
  const fs::path root = fs::path(SHADERPORT_SOURCE_DIR) / "tests" / "rules";
  for (const auto& dir : fs::directory_iterator(root)) {
    const std::string name = dir.path().filename().string();
    if (!dir.is_directory() || !name.starts_with(prefix)) continue;
    const std::string rule_id = std::string(category) + "/" + name.substr(prefix.size());
    for (const auto& file : fs::directory_iterator(dir.path())) {
      const std::string file_name = file.path().filename().string();
      const std::string ext = file.path().extension().string();
      if ((ext == ".frag" || ext == ".vert" || ext == ".glsl") &&
          file_name.find(".out.") == std::string::npos) {
        cases.push_back({file.path(), rule_id});
      }
    }
  }
  std::sort(cases.begin(), cases.end(),
            [](const GoldenCase& a, const GoldenCase& b) { return a.input < b.input; });
  return cases;
}

}  // namespace shaderport::testing
