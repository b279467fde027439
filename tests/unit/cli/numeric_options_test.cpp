// Numeric options are refused unless finite and in range: NaN passes every `<= 0`
// test, and sscanf's %u reads "-1" as 4294967295.
#include <gtest/gtest.h>

#include <string>

#include "cli/cli_test_util.h"
#include "cli/temp_project.h"

namespace shaderport::testing {
namespace {

constexpr const char* kImage = "void mainImage(out vec4 c, in vec2 p) { c = vec4(0.5); }\n";

TEST(NumericOptionsCli, RenderTimeoutMustBeFiniteAndInRange) {
  TempProject project("numeric-timeout");
  project.Write("s.frag", kImage);
  for (const std::string value : {"nan", "inf", "-inf", "1e10", "0", "-1"}) {
    const CommandResult check =
        RunShaderport("check --render --render-timeout " + value + " s.frag", project.Root());
    EXPECT_EQ(check.exit_code, 2) << value << check.out << check.err;
    EXPECT_NE(check.err.find("shaderport: error: --render-timeout"), std::string::npos)
        << check.err;
    const CommandResult render =
        RunShaderport("render --timeout " + value + " s.frag", project.Root());
    EXPECT_EQ(render.exit_code, 2) << value << render.out << render.err;
    EXPECT_NE(render.err.find("shaderport: error: --timeout"), std::string::npos) << render.err;
  }
}

TEST(NumericOptionsCli, RenderSizeRefusesSignsAndWrapping) {
  TempProject project("numeric-size");
  project.Write("s.frag", kImage);
  for (const std::string size : {"-4294967295x-4294967295", "-1x-1", "4294967297x1", "+8x8", "8x8x",
                                 "8 x8", "0x8", "x8", "4097x1"}) {
    const CommandResult result =
        RunShaderport("render '--size=" + size + "' s.frag -o out.png", project.Root());
    EXPECT_EQ(result.exit_code, 2) << size << result.out << result.err;
    EXPECT_NE(result.err.find("shaderport: error: --size"), std::string::npos) << result.err;
    EXPECT_FALSE(project.Exists("out.png")) << size;
  }
}

TEST(NumericOptionsCli, OtherNumbersAreCheckedToo) {
  TempProject project("numeric-time");
  project.Write("s.frag", kImage);
  for (const std::string args :
       {"render --time nan s.frag", "render --mouse 1,inf s.frag", "render --frame -5 s.frag",
        "report --html r.html --timeout nan s.frag", "port -j -1 s.frag"}) {
    const CommandResult result = RunShaderport(args, project.Root());
    EXPECT_EQ(result.exit_code, 2) << args << result.err;
    EXPECT_EQ(result.err.rfind("shaderport: error: ", 0), 0u) << args << result.err;
  }
  EXPECT_FALSE(project.Exists("r.html"));
}

}  // namespace
}  // namespace shaderport::testing
