// The WebGL conformance cases of conformance/glsl/implicit that must fail
// (GLSL ES has no implicit int -> float conversion): the real binary's `check`
// rejects each, and after `shaderport fix` the same `check` accepts it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/cli_test_util.h"

namespace shaderport::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct ImplicitCase {
  std::string id;
  std::string file_name;  // e.g. add_int_mat3.vert
  std::string code;       // the stage expected to fail
};

std::vector<ImplicitCase> ExpectedFailures() {
  std::vector<ImplicitCase> cases;
  std::ifstream in(fs::path(SHADERPORT_SHARED_DIR) / "conformance/webgl-cts.jsonl");
  std::string line;
  while (std::getline(in, line)) {
    const json c = json::parse(line);
    if (c.value("folder", "").find("implicit") == std::string::npos) continue;
    const json& expected = c["expected"];
    const std::string base = fs::path(c.value("file", "")).stem().stem().string();
    if (expected.value("vShaderSuccess", json(true)) == json(false)) {
      cases.push_back({c["id"], base + ".vert", c["vertex"]});
    }
    if (expected.value("fShaderSuccess", json(true)) == json(false)) {
      cases.push_back({c["id"], base + ".frag", c["fragment"]});
    }
  }
  return cases;
}

bool OnlyInsertions(const std::string& original, const std::string& fixed) {
  size_t at = 0;
  for (char c : fixed) {
    if (at < original.size() && original[at] == c) ++at;
  }
  return at == original.size();
}

TEST(ImplicitConformance, CheckRejectsThenFixRepairs) {
  const std::vector<ImplicitCase> cases = ExpectedFailures();
  ASSERT_EQ(cases.size(), 37u);
  const fs::path dir =
      fs::temp_directory_path() / ("shaderport-implicit-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);

  size_t rejected = 0, repaired = 0;
  for (const ImplicitCase& c : cases) {
    SCOPED_TRACE(c.id);
    std::ofstream(dir / c.file_name, std::ios::binary) << c.code;
    const CommandResult check = RunShaderport("check '" + c.file_name + "'", dir);
    EXPECT_EQ(check.exit_code, 1) << check.out << check.err;
    rejected += check.exit_code == 1;

    const CommandResult fix = RunShaderport("fix '" + c.file_name + "'", dir);
    EXPECT_NE(fix.exit_code, 3) << fix.err;  // never an internal error
    const std::string fixed_name = "fixed-" + c.file_name;
    std::ofstream(dir / fixed_name, std::ios::binary) << fix.out;
    const CommandResult recheck = RunShaderport("check '" + fixed_name + "'", dir);
    EXPECT_EQ(recheck.exit_code, 0) << "fixed:\n" << fix.out << recheck.out << recheck.err;
    // It means the same: the fix only inserts conversions (`1` -> `1.0`,
    // `x` -> `float(x)`), so the original is a subsequence of the fixed text.
    EXPECT_NE(fix.out, c.code);
    EXPECT_TRUE(OnlyInsertions(c.code, fix.out)) << fix.out;
    repaired += recheck.exit_code == 0;
  }
  fs::remove_all(dir);
  EXPECT_EQ(rejected, cases.size());
  EXPECT_EQ(repaired, cases.size());
  std::printf("implicit conformance: %zu cases, %zu rejected by check, %zu repaired by fix\n",
              cases.size(), rejected, repaired);
}

}  // namespace
}  // namespace shaderport::testing
