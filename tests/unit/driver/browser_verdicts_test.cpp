// `check --target` gives Chromium's verdict on every shader of tests/browser-verdicts:
// the smallest shaders of each disagreement class the differential run found
// (tools/browser/differential.py), with the verdict headless Chromium gave, recorded by
// tools/browser/record_verdicts.py into verdicts.json (never edited by hand). The
// folder a shader sits in (webgl1/, webgl2/) is the context it was compiled in;
// projects/ holds ShaderToy projects: each pass compiled with Common as the site does
// ("projects/NAME.json#TAB") and the Common tab alone ("...#Common"). The site runs a
// pass when both compile; check rejects a pass for an error in it or in Common.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "driver/check_pipeline.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = fs::path(SHADERPORT_SOURCE_DIR) / "tests" / "browser-verdicts";

bool IsLinkRule(const std::string& id) { return id.starts_with("link/"); }

// First error of each file, "" when check accepts it; by path relative to kDir.
std::map<std::string, std::string> FirstErrors(const std::string& context, model::Target target) {
  CheckOptions options;
  options.paths = {kDir / context};
  options.target = target;
  options.use_config = false;
  std::map<std::string, std::string> errors;
  for (const FileReport& report : RunCheck(options).report.files) {
    std::string first;
    for (const Diagnostic& diagnostic : report.diagnostics) {
      if (diagnostic.severity != Severity::kError || IsLinkRule(diagnostic.rule_id)) continue;
      first = diagnostic.rule_id + ": " + diagnostic.message;
      break;
    }
    const fs::path path = fs::path(report.file->Name()).lexically_normal();
    errors[fs::relative(path, kDir).generic_string()] = first;
  }
  return errors;
}

// The same for the passes of the projects: a pass's own first error, else Common's.
std::map<std::string, std::string> ProjectPassErrors() {
  std::map<std::string, std::string> tabs = FirstErrors("projects", model::Target::kWebGL2);
  std::map<std::string, std::string> errors;
  for (const auto& [tab, error] : tabs) {
    const size_t hash = tab.find('#');
    if (hash == std::string::npos) continue;
    const auto common = tabs.find(tab.substr(0, hash) + "#Common");
    errors[tab] = !error.empty() || common == tabs.end() ? error : common->second;
  }
  return errors;
}

TEST(BrowserVerdicts, CheckGivesChromiumsVerdict) {
  std::ifstream in(kDir / "verdicts.json");
  ASSERT_TRUE(in) << "missing " << (kDir / "verdicts.json");
  const nlohmann::json verdicts = nlohmann::json::parse(in);
  std::map<std::string, std::string> errors = FirstErrors("webgl1", model::Target::kWebGL1);
  errors.merge(FirstErrors("webgl2", model::Target::kWebGL2));
  errors.merge(ProjectPassErrors());
  ASSERT_EQ(errors.size(), verdicts.size()) << "every shader needs a recorded verdict";
  size_t cases = 0;
  for (const auto& [file, verdict] : verdicts.items()) {
    ASSERT_TRUE(errors.contains(file)) << file << " was not checked";
    bool browser = verdict.at("compiled").get<bool>();
    if (const size_t hash = file.find('#'); hash != std::string::npos) {
      const std::string common = file.substr(0, hash) + "#Common";
      if (verdicts.contains(common))
        browser = browser && verdicts[common].at("compiled").get<bool>();
    }
    const std::string& error = errors[file];
    EXPECT_EQ(browser, error.empty())
        << file << ": Chromium " << (browser ? "compiles it" : "rejects it: ")
        << verdict.value("log", "") << "; check " << (error.empty() ? "accepts it" : error);
    ++cases;
  }
  EXPECT_GT(cases, 10u);
}

}  // namespace
}  // namespace shaderport::driver
