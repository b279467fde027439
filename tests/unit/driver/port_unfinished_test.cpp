// What a port or fix that could not finish hands back: text past a resource limit, or
// fixes that never settled. Neither may be written or given to glslang (issue 31).
#include <gtest/gtest.h>

#include <string>

#include "driver/port/port_file.h"
#include "driver/port/port_report.h"
#include "rule/test_rules.h"
#include "source/source_manager.h"

namespace shaderport::driver {
namespace {

// x -> y -> x: the two rules undo each other every round.
TEST(PortUnfinished, FixesThatDoNotSettleGiveTheInputAndNoOutput) {
  const rule::testing::RenameRule there("test/there", "x", "y");
  const rule::testing::RenameRule back("test/back", "y", "x");
  SourceManager sources;
  const std::string text = "precision mediump float;\nfloat x;\nvoid main() { x = 1.0; }\n";
  const SourceFile& file = sources.Add("cycle.frag", text);
  PortOptions options;
  options.mode = rule::PortMode::kFix;
  options.rules = {&there, &back};
  const PortResult result = PortSource(file, nullptr, options, sources);
  EXPECT_FALSE(result.converged);
  EXPECT_FALSE(result.HasOutput());
  EXPECT_EQ(result.text, text);
  EXPECT_FALSE(AllConverged(std::span(&result, 1)));
  bool named = false;
  for (const Diagnostic& d : result.diagnostics) {
    named = named || (d.rule_id == "internal/error" &&
                      d.message.find("test/back, test/there") != std::string::npos);
    EXPECT_EQ(d.rule_id.rfind("glslang/", 0), std::string::npos) << "glslang ran: " << d.message;
  }
  EXPECT_TRUE(named);
}

// A stray ')' and code after the closing brace (a mutated real pass): the parser's
// recovery put the main() the port added out of the tree's reach, and it was added
// again every round until the engine gave up (exit 3; found by the mutation sweep).
TEST(PortUnfinished, MainIsAddedOnceWhereRecoveryHidesIt) {
  SourceManager sources;
  const SourceFile& file =
      sources.Add("stray.glsl",
                  "void mainImage( out vec4 fragColor, in vec2 fragCoord )\n{\n    vec2 uv = "
                  "fragCoord/iResolution.xy;\n    fragColor = uv);\n} texture(iChannel0,\n");
  const PortResult result = PortSource(file, nullptr, PortOptions{}, sources);
  EXPECT_TRUE(result.converged);
  for (const Diagnostic& d : result.diagnostics)
    EXPECT_NE(d.rule_id, "internal/error") << d.message;
}

// A duplicated #ifdef leaves the group open: the main() the port added landed in text
// that is not compiled, and was added every round (mutation sweep, exit 3).
TEST(PortUnfinished, MainIsNotAddedWhereAnOpenIfHidesIt) {
  SourceManager sources;
  const SourceFile& file = sources.Add(
      "open-if.glsl",
      "void mainImage(out vec4 o, in vec2 u) {\n  o = vec4(1.0);\n#ifdef NEVER\n#ifdef NEVER\n"
      "  o = vec4(0.0);\n#endif\n}\n");
  const PortResult result = PortSource(file, nullptr, PortOptions{}, sources);
  EXPECT_TRUE(result.converged);
  for (const Diagnostic& d : result.diagnostics)
    EXPECT_NE(d.rule_id, "internal/error") << d.message;
}

// 10,100 nested parentheses: past the parser's limit. Only the breach is reported.
TEST(PortUnfinished, TextPastALimitIsReportedNotPorted) {
  SourceManager sources;
  const std::string text = "void mainImage(out vec4 c, in vec2 p) {\n  c = vec4" +
                           std::string(10100, '(') + "1.0" + std::string(10100, ')') + ";\n}\n";
  const SourceFile& file = sources.Add("deep.glsl", text);
  const PortResult result = PortSource(file, nullptr, PortOptions{}, sources);
  EXPECT_TRUE(result.limit_breached);
  EXPECT_TRUE(result.converged);
  EXPECT_FALSE(result.HasOutput());
  EXPECT_EQ(result.text, text);
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].rule_id, "syntax/nesting-too-deep");
}

}  // namespace
}  // namespace shaderport::driver
