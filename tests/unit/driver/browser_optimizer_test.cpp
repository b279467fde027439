// The browser's optimiser on a render's text: Chromium's regroupings, and no run on a
// module whose inlining would explode (docs/limits.md, kMaxInlinedInstructions).
#include "driver/render_check/browser_optimizer.h"

#include <gtest/gtest.h>

#include <string>

namespace shaderport::driver {
namespace {

const std::string kHead =
    "#version 300 es\nprecision highp float;\nuniform float u;\nlayout(location = 0) out vec4 "
    "o;\n";

TEST(BrowserOptimizer, FactorsAsChromiumsOptimiserDoes) {
  const auto text = OptimizeAsBrowser(kHead + "void main() { o = vec4(u * 0.25 + u * 0.5); }\n");
  ASSERT_TRUE(text.has_value());
  EXPECT_NE(text->find("u * 0.75"), std::string::npos) << *text;  // a * b + a * c = a * (b + c)
}

TEST(BrowserOptimizer, SkipsAModuleWhoseInliningWouldExplode) {
  // Each level calls the one below 8 times: 8^5 copies of the leaf once inlined.
  std::string body = "float f0(float x) { return sin(x) * x + cos(x * 2.0) / (x + 1.0); }\n";
  for (int level = 1; level <= 5; ++level) {
    const std::string callee = "f" + std::to_string(level - 1);
    body += "float f" + std::to_string(level) + "(float x) { return ";
    for (int call = 0; call < 8; ++call) {
      body += (call > 0 ? " + " : "") + callee + "(x + " + std::to_string(call) + ".0)";
    }
    body += "; }\n";
  }
  // The same functions called through one level compile and optimise: what stops the
  // deep call is its inlined size, not the code.
  EXPECT_TRUE(OptimizeAsBrowser(kHead + body + "void main() { o = vec4(f1(u)); }\n").has_value());
  EXPECT_FALSE(OptimizeAsBrowser(kHead + body + "void main() { o = vec4(f5(u)); }\n").has_value());
}

TEST(BrowserOptimizer, TextGlslangRejectsAs310IsLeftAlone) {
  EXPECT_FALSE(OptimizeAsBrowser(kHead + "void main() { float buffer = u; o = vec4(buffer); }\n")
                   .has_value());
}

}  // namespace
}  // namespace shaderport::driver
