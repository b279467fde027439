// End-to-end porting goldens: every shader of corpus/ (except the seed's broken
// excerpts) and the custom-dialect inputs of tests/data/port/ go through
// PortFile; the output must equal tests/golden/port/<path>.out.<frag|vert>
// (SHADERPORT_UPDATE_GOLDENS=1 rewrites them), compile in glslang as GLSL ES
// 3.00, and come out of a second port unchanged.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_test_util.h"
#include "driver/port/port_file.h"
#include "source/source_manager.h"
#include "validate/glslang_validator.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;

struct GoldenCase {
  fs::path input;   // absolute
  fs::path golden;  // without the .out.<stage> suffix
  std::string label;
};

// gtest prints a case by its input path, not its bytes.
void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.input.string(); }

std::string Label(const fs::path& relative) {
  std::string label;
  for (char c : relative.generic_string())
    label += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return label;
}

// corpus/MANIFEST rows (tab separated: path origin dialect stage expect), then tests/data/port/.
std::vector<GoldenCase> Cases() {
  const fs::path source = SHADERPORT_SOURCE_DIR;
  const fs::path golden_dir = source / "tests/golden/port";
  std::vector<GoldenCase> cases;
  std::ifstream manifest(source / "corpus/MANIFEST");
  std::string line;
  std::getline(manifest, line);  // header
  while (std::getline(manifest, line)) {
    std::vector<std::string> fields;
    std::istringstream row(line);
    for (std::string field; std::getline(row, field, '\t');) fields.push_back(field);
    if (fields.size() < 5 || fields[4].rfind("seed-error", 0) == 0) continue;
    cases.push_back({source / "corpus" / fields[0], golden_dir / fields[0], Label(fields[0])});
  }
  std::vector<fs::path> custom;
  for (const auto& entry : fs::directory_iterator(source / "tests/data/port")) {
    custom.push_back(entry.path());
  }
  std::sort(custom.begin(), custom.end());
  for (const fs::path& path : custom) {
    const fs::path relative = fs::path("custom") / path.filename();
    cases.push_back({path, golden_dir / relative, Label(relative)});
  }
  return cases;
}

validate::ValidationResult CompileAsEssl300(const std::string& text, model::Stage stage,
                                            SourceManager& sources) {
  const SourceFile& file = sources.Add("golden", text, /*synthetic=*/true);
  validate::ValidationRequest request;
  request.parts.push_back({file.Name(), file.Text(), file.Id()});
  request.stage = stage;
  request.default_version = 100;  // the output must carry `#version 300 es` itself
  request.link = true;
  return validate::ValidateWithGlslang(request);
}

std::string Errors(const DiagnosticList& diagnostics) {
  std::string out;
  for (const Diagnostic& d : diagnostics) out += d.rule_id + ": " + d.message + "\n";
  return out;
}

class PortGolden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(PortGolden, OutputMatchesGoldenCompilesAndIsStable) {
  const GoldenCase& c = GetParam();
  SourceManager sources;
  const PortResult result = PortFile(c.input, PortOptions{}, sources);
  ASSERT_FALSE(result.read_failed) << Errors(result.diagnostics);
  EXPECT_TRUE(result.validated) << Errors(result.diagnostics);

  const std::string extension =
      result.output_stage == model::Stage::kVertex ? ".out.vert" : ".out.frag";
  fs::path golden = c.golden;
  golden += extension;
  EXPECT_TRUE(testing::MatchesGolden(result.text, golden));

  // The committed golden itself must be valid WebGL2.
  const std::string committed = testing::ReadWholeFile(golden);
  EXPECT_EQ(committed.rfind("#version 300 es\n", 0), 0u) << golden;
  const validate::ValidationResult compiled =
      CompileAsEssl300(committed, result.output_stage, sources);
  EXPECT_TRUE(compiled.Accepted(true)) << golden << "\n" << Errors(compiled.diagnostics);

  // Porting what port made changes nothing.
  fs::path again_name = c.golden.filename();
  again_name += extension;
  const SourceFile& output = sources.Add(again_name.string(), result.text);
  const PortResult again = PortSource(output, nullptr, PortOptions{}, sources);
  EXPECT_EQ(again.text, result.text) << "a second port changed " << golden;
  EXPECT_TRUE(again.fixed.empty()) << Errors(again.fixed);
}

INSTANTIATE_TEST_SUITE_P(Corpus, PortGolden, ::testing::ValuesIn(Cases()),
                         [](const ::testing::TestParamInfo<GoldenCase>& param_info) {
                           return param_info.param.label;
                         });

TEST(PortGoldenSet, CoversCorpusAndCustomDialects) {
  const std::vector<GoldenCase> cases = Cases();
  size_t custom = 0;
  for (const GoldenCase& c : cases) custom += c.label.rfind("custom_", 0) == 0;
  EXPECT_GE(custom, 3u);
  EXPECT_GE(cases.size() - custom, 35u);  // corpus rows that are not seed errors
}

}  // namespace
}  // namespace shaderport::driver
