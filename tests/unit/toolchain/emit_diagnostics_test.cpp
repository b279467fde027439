// What the SPIR-V leg reports instead of output: leg limitations, invalid input, bad options,
// SPIRV-Cross exceptions. Never a crash.
#include <gtest/gtest.h>

#include "emit_test_util.h"

namespace shaderport::toolchain {
namespace {

using testing::EmitText;
using testing::GlslangErrors;
using testing::OptionsFor;
using testing::RuleIds;

constexpr const char* kBufferName =
    "#version 300 es\nprecision highp float;\nout vec4 color;\n"
    "void main() {\n  float buffer = 0.5;\n  color = vec4(buffer);\n}\n";

TEST(EmitDiagnostics, A310esReservedWordIsALegLimitationOnItsLine) {
  ASSERT_EQ(GlslangErrors(kBufferName, model::Stage::kFragment), "") << "valid WebGL2 shader";
  const SourceFile file(3, "buffer.frag", kBufferName);
  const EmitResult result = Emit(file, model::Stage::kFragment, OptionsFor(EmitKind::kHlsl));
  ASSERT_FALSE(result.diagnostics.empty());
  EXPECT_TRUE(result.output.empty());
  for (const Diagnostic& d : result.diagnostics) {
    EXPECT_EQ(d.rule_id, "spirv/leg-limitation");
    EXPECT_NE(d.message.find("SPIR-V leg"), std::string::npos) << d.message;
  }
  const Diagnostic& first = result.diagnostics.front();
  EXPECT_EQ(first.severity, Severity::kError);
  EXPECT_EQ(first.range.file, 3u);
  EXPECT_EQ(file.LocationOf(first.range.begin).line, 5u);
  EXPECT_NE(first.message.find("BUFFER"), std::string::npos) << first.message;
}

TEST(EmitDiagnostics, InvalidEsslIsInvalidInputNotALegLimitation) {
  const std::string text =
      "#version 300 es\nprecision highp float;\nout vec4 color;\n"
      "void main() {\n  float x = 1;\n  color = vec4(x);\n}\n";
  ASSERT_NE(GlslangErrors(text, model::Stage::kFragment), "");  // the helper can say no
  const SourceFile file(0, "bad.frag", text);
  const EmitResult result = Emit(file, model::Stage::kFragment, OptionsFor(EmitKind::kSpirv));
  ASSERT_FALSE(result.diagnostics.empty());
  EXPECT_EQ(result.diagnostics.front().rule_id, "spirv/invalid-input");
  EXPECT_EQ(file.LocationOf(result.diagnostics.front().range.begin).line, 5u);
  EXPECT_TRUE(result.output.empty());
}

TEST(EmitDiagnostics, MissingMainIsInvalidInput) {
  const EmitResult result = EmitText("#version 300 es\nfloat f() { return 1.0; }\n",
                                     model::Stage::kVertex, OptionsFor(EmitKind::kSpvasm));
  ASSERT_FALSE(result.diagnostics.empty()) << result.output;
  EXPECT_EQ(result.diagnostics.front().rule_id, "spirv/invalid-input");
}

TEST(EmitDiagnostics, UnknownOptimisationLevelIsRejectedBeforeCompiling) {
  EmitOptions options = OptionsFor(EmitKind::kSpirv);
  options.optimize = "O3";
  const EmitResult result = EmitText(kBufferName, model::Stage::kFragment, options);
  ASSERT_EQ(result.diagnostics.size(), 1u) << RuleIds(result.diagnostics);
  EXPECT_EQ(result.diagnostics[0].rule_id, "spirv/unknown-optimization");
  EXPECT_NE(result.diagnostics[0].message.find("O3"), std::string::npos);
}

TEST(EmitDiagnostics, OutOfRangeTargetVersionsAreRejected) {
  const std::string text = "#version 300 es\nvoid main() { gl_Position = vec4(0.0); }\n";
  EmitOptions hlsl = OptionsFor(EmitKind::kHlsl);
  hlsl.hlsl_shader_model = 7;
  EXPECT_EQ(RuleIds(EmitText(text, model::Stage::kVertex, hlsl).diagnostics)
                .rfind("spirv/unsupported-option", 0),
            0u);
  EmitOptions msl = OptionsFor(EmitKind::kMsl);
  msl.msl_version = 2;
  EXPECT_EQ(RuleIds(EmitText(text, model::Stage::kVertex, msl).diagnostics)
                .rfind("spirv/unsupported-option", 0),
            0u);
}

// SPIRV-Cross throws for texelFetch in shader model 3; the adapter turns that into a diagnostic.
TEST(EmitDiagnostics, SpirvCrossExceptionsBecomeDiagnostics) {
  const std::string text =
      "#version 300 es\nprecision highp float;\nuniform sampler2D tex;\nout vec4 color;\n"
      "void main() { color = texelFetch(tex, ivec2(gl_FragCoord.xy), 0); }\n";
  EmitOptions options = OptionsFor(EmitKind::kHlsl);
  options.hlsl_shader_model = 30;
  const EmitResult result = EmitText(text, model::Stage::kFragment, options);
  ASSERT_EQ(result.diagnostics.size(), 1u) << result.output;
  EXPECT_EQ(result.diagnostics[0].rule_id, "spirv/cross-compile-failed");
  EXPECT_NE(result.diagnostics[0].message.find("SPIRV-Cross"), std::string::npos);
  EXPECT_TRUE(result.output.empty());
  options.hlsl_shader_model = 50;
  EXPECT_TRUE(EmitText(text, model::Stage::kFragment, options).diagnostics.empty());
}

// glslang 12 puts a plain bool uniform in UniformConstant, which SPIR-V forbids: the validator
// must catch it rather than let an invalid module through.
TEST(EmitDiagnostics, GlslangModulesTheValidatorRejectsAreInvalidModule) {
  const std::string text =
      "#version 300 es\nprecision highp float;\nuniform bool enabled;\nout vec4 color;\n"
      "void main() { color = enabled ? vec4(1.0) : vec4(0.0); }\n";
  ASSERT_EQ(GlslangErrors(text, model::Stage::kFragment), "");
  const EmitResult result = EmitText(text, model::Stage::kFragment, OptionsFor(EmitKind::kSpirv));
  ASSERT_EQ(result.diagnostics.size(), 1u) << result.output.size();
  EXPECT_EQ(result.diagnostics[0].rule_id, "spirv/invalid-module");
  EXPECT_NE(result.diagnostics[0].message.find("OpTypeBool"), std::string::npos)
      << result.diagnostics[0].message;
  EXPECT_TRUE(result.output.empty());
}

TEST(EmitDiagnostics, HostileInputNeverCrashes) {
  const std::string deep =
      "#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() { "
      "float x = " +
      std::string(3000, '(') + "1.0" + std::string(3000, ')') + "; c = vec4(x); }\n";
  for (const EmitKind kind : {EmitKind::kSpirv, EmitKind::kEsslRoundtrip, EmitKind::kReflect}) {
    const EmitResult result = EmitText(deep, model::Stage::kFragment, OptionsFor(kind));
    EXPECT_TRUE(!result.output.empty() || HasErrors(result.diagnostics));
  }
  for (const char* garbage : {"", "\x01\x02\x03", "#version 300 es\n}}}}", "#version 999\n"}) {
    const EmitResult result =
        EmitText(garbage, model::Stage::kFragment, OptionsFor(EmitKind::kSpirv));
    EXPECT_TRUE(HasErrors(result.diagnostics)) << garbage;
    EXPECT_TRUE(result.output.empty());
  }
}

// f_i calls f_{i-1} twice, 30 deep: 2^30 copies once inlined. spirv-opt and SPIRV-Cross
// ran for minutes; now the optimiser is skipped and SPIRV-Cross refused, at once.
std::string DoublingCalls(int depth) {
  std::string text =
      "#version 300 es\nprecision highp float;\nout vec4 color;\n"
      "float f0(float x) { return sin(x) * 1.5 + x; }\n";
  for (int i = 1; i <= depth; ++i) {
    const std::string f = "f" + std::to_string(i), g = "f" + std::to_string(i - 1);
    text += "float " + f + "(float x) { return " + g + "(x) + " + g + "(x * 0.5); }\n";
  }
  return text + "void main() { color = vec4(f" + std::to_string(depth) + "(1.0)); }\n";
}

TEST(EmitDiagnostics, ExponentialInliningSkipsTheOptimiserAndRefusesSpirvCross) {
  const std::string text = DoublingCalls(30);
  EmitOptions spirv = OptionsFor(EmitKind::kSpirv);
  spirv.optimize = "O";
  const EmitResult optimised = EmitText(text, model::Stage::kFragment, spirv);
  EXPECT_FALSE(optimised.output.empty());
  ASSERT_EQ(optimised.diagnostics.size(), 1u) << RuleIds(optimised.diagnostics);
  EXPECT_EQ(optimised.diagnostics[0].rule_id, "spirv/inlining-too-large");
  EXPECT_EQ(optimised.diagnostics[0].severity, Severity::kWarning);
  EXPECT_EQ(optimised.words_after, optimised.words_before);
  for (const EmitKind kind :
       {EmitKind::kHlsl, EmitKind::kMsl, EmitKind::kEsslRoundtrip, EmitKind::kReflect}) {
    const EmitResult crossed = EmitText(text, model::Stage::kFragment, OptionsFor(kind));
    EXPECT_TRUE(crossed.output.empty()) << EmitKindName(kind);
    ASSERT_EQ(crossed.diagnostics.size(), 1u) << RuleIds(crossed.diagnostics);
    EXPECT_EQ(crossed.diagnostics[0].rule_id, "spirv/inlining-too-large");
    EXPECT_EQ(crossed.diagnostics[0].severity, Severity::kError);
  }
  // A shallow chain is optimised and cross-compiled as before.
  const EmitResult shallow = EmitText(DoublingCalls(4), model::Stage::kFragment, spirv);
  EXPECT_TRUE(shallow.diagnostics.empty()) << RuleIds(shallow.diagnostics);
}

}  // namespace
}  // namespace shaderport::toolchain
