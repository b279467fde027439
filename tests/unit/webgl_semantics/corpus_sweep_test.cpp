// Every pass of the ShaderToy corpus, composed as the site does: whenever glslang
// compiles the text, it also compiles the text render hands Mesa (all browser
// semantics and the render probe applied), with the same number of lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "glsl/webgl_semantics/browser_semantics.h"
#include "sema/glslang_oracle.h"
#include "source/source_manager.h"
#include "validate/shadertoy_contract.h"

namespace shaderport::glsl {
namespace {

TEST(BrowserSemanticsSweep, CorpusStillCompilesAfterTheTransforms) {
  std::ifstream in(std::string(SHADERPORT_SHARED_DIR) + "/corpus-shadertoy/permissive.jsonl");
  if (!in.good()) GTEST_SKIP() << "no shared ShaderToy corpus";
  size_t compiled = 0, changed = 0;
  BrowserSemanticsOptions options;
  options.zero_out_parameters = true;
  options.add_render_probe = true;
  options.cpu_browser_math = true;
  options.source_order_arithmetic = true;  // as render applies them
  std::string line;
  while (std::getline(in, line)) {
    const auto record = nlohmann::json::parse(line);
    std::string common;
    for (const auto& pass : record["passes"]) {
      if (pass["type"] == "common") common = pass["code"].get<std::string>() + "\n";
    }
    for (const auto& pass : record["passes"]) {
      const auto type = model::ParsePassKind(pass["type"].get<std::string>());
      if (!type || *type == model::PassKind::kSound || *type == model::PassKind::kCube ||
          *type == model::PassKind::kCommon) {
        continue;
      }
      const std::string text = validate::ShaderToyHeader(*type, {}) + common +
                               pass["code"].get<std::string>() + "\n" +
                               validate::ShaderToyEpilogue(*type);
      if (!testing::CompileWithGlslang(text, model::Stage::kFragment).ok) continue;
      ++compiled;
      SourceManager sources;
      const SourceFile& file = sources.Add(record["id"].get<std::string>(), text);
      const SourceFile* parts[] = {&file};
      const auto result = ApplyBrowserSemantics(parts, options);
      const std::string& edited = result.texts.front();
      if (edited == text) continue;
      ++changed;
      EXPECT_EQ(std::count(edited.begin(), edited.end(), '\n'),
                std::count(text.begin(), text.end(), '\n'))
          << file.Name();
      const auto again = testing::CompileWithGlslang(edited, model::Stage::kFragment);
      EXPECT_TRUE(again.ok) << file.Name() << "\n" << again.log;
    }
  }
  EXPECT_GT(compiled, 900U);
  EXPECT_GT(changed, 900U);  // the probe alone changes every pass with a single output
  std::cout << compiled << " passes compile, " << changed << " changed by the transforms\n";
}

}  // namespace
}  // namespace shaderport::glsl
