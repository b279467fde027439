// Applies the browser-semantics transforms to a small fragment (or vertex) shader
// and checks what every output must keep: its line count, and that glslang
// compiles it.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <string_view>

#include "glsl/webgl_semantics/browser_semantics.h"
#include "sema/glslang_oracle.h"
#include "source/source_manager.h"

namespace shaderport::glsl::testing_support {

inline constexpr std::string_view kHead =
    "#version 300 es\nprecision highp float;\nprecision highp int;\nout vec4 o;\n";

inline BrowserSemanticsResult Apply(std::string_view body, BrowserSemanticsOptions options = {}) {
  SourceManager sources;
  const SourceFile& file = sources.Add("t.frag", std::string(kHead) + std::string(body));
  const SourceFile* parts[] = {&file};
  BrowserSemanticsResult result = ApplyBrowserSemantics(parts, options);
  const std::string& text = result.texts.front();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'),
            std::count(file.Text().begin(), file.Text().end(), '\n'));
  const auto compiled = testing::CompileWithGlslang(
      text, options.vertex_stage ? model::Stage::kVertex : model::Stage::kFragment);
  EXPECT_TRUE(compiled.ok) << text << "\n" << compiled.log;
  return result;
}

inline std::string Body(const BrowserSemanticsResult& result) {
  return result.texts.front().substr(kHead.size());
}

}  // namespace shaderport::glsl::testing_support
