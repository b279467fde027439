// Every rule id the sources report must be in the catalog, so that SARIF, `explain`
// and docs/rules.md describe it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "diag/rule_catalog.h"

namespace shaderport {
namespace {

TEST(RuleCatalogCoverageTest, EveryIdInTheSourcesIsCatalogued) {
  const std::regex id_literal(
      "\"((input|lex|preprocessor|syntax|semantic|glslang|internal|config|suppression|dialect|"
      "webgl|webgl2|portability|shadertoy|typing|spirv|render|port)/[a-z0-9]+(-[a-z0-9]+)*)\"");
  std::set<std::string> missing;
  size_t ids = 0;
  const std::filesystem::path root = SHADERPORT_SOURCE_DIR;
  for (const char* dir : {"src", "rules", "tools"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root / dir)) {
      const std::string extension = entry.path().extension().string();
      if (extension != ".cpp" && extension != ".h") continue;
      std::ifstream in(entry.path());
      std::stringstream text;
      text << in.rdbuf();
      const std::string content = text.str();
      for (std::sregex_iterator it(content.begin(), content.end(), id_literal), end; it != end;
           ++it) {
        ++ids;
        const std::string id = (*it)[1].str();
        if (FindRule(id) == nullptr)
          missing.insert(id + " (" + entry.path().filename().string() + ")");
      }
    }
  }
  EXPECT_GT(ids, 100u);
  for (const std::string& id : missing) ADD_FAILURE() << "not in the catalog: " << id;
}

}  // namespace
}  // namespace shaderport
