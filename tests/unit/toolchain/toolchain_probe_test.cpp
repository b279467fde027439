// Smoke tests: each external shader library is linked and really does its job.
#include "toolchain/toolchain_probe.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace shaderport::toolchain {
namespace {

// Probing creates an OSMesa context, so do it once for the whole suite.
class ToolchainProbeTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { report_ = new ToolchainReport(ProbeToolchain()); }
  static void TearDownTestSuite() {
    delete report_;
    report_ = nullptr;
  }
  static const ToolchainReport& Report() { return *report_; }

 private:
  static ToolchainReport* report_;
};

ToolchainReport* ToolchainProbeTest::report_ = nullptr;

// Validates `text` with glslang the way the project checks ESSL: no SPIR-V target.
bool GlslangAccepts(const std::string& text, std::string& log) {
  glslang::InitializeProcess();
  glslang::TShader shader(EShLangFragment);
  const char* source = text.c_str();
  shader.setStrings(&source, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, EShLangFragment, glslang::EShClientNone, 0);
  shader.setEnvClient(glslang::EShClientNone, static_cast<glslang::EShTargetClientVersion>(0));
  shader.setEnvTarget(glslang::EShTargetNone, static_cast<glslang::EShTargetLanguageVersion>(0));
  bool ok = shader.parse(GetDefaultResources(), 100, false, EShMsgCascadingErrors);
  log = shader.getInfoLog();
  if (!ok) return false;
  glslang::TProgram program;
  program.addShader(&shader);
  ok = program.link(EShMsgDefault);
  log += program.getInfoLog();
  return ok;
}

TEST_F(ToolchainProbeTest, EveryStepSucceeds) { EXPECT_EQ(Report().error, ""); }

TEST_F(ToolchainProbeTest, ReportsGlslangVersion) {
  // Debian 12 ships glslang 12.x; the probe formats it as major.minor.patch.
  const std::string& version = Report().glslang_version;
  ASSERT_FALSE(version.empty());
  EXPECT_EQ(std::count(version.begin(), version.end(), '.'), 2) << version;
  EXPECT_NE(version, "0.0.0");
}

TEST_F(ToolchainProbeTest, GlslangProducesSpirv) {
  // A SPIR-V module has a 5-word header, so a real shader is well above that.
  EXPECT_GT(Report().spirv_words, 5u);
}

TEST_F(ToolchainProbeTest, SpirvToolsValidatesTheModule) { EXPECT_TRUE(Report().spirv_valid); }

TEST_F(ToolchainProbeTest, SpirvCrossEmitsEssl300) {
  const std::string& text = Report().cross_compiled;
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.rfind("#version 300 es", 0), 0u) << text;
  EXPECT_NE(text.find("void main()"), std::string::npos) << text;
  // The probe shader's constant colour survives the round trip.
  EXPECT_NE(text.find("0.25"), std::string::npos) << text;
}

TEST_F(ToolchainProbeTest, CrossCompiledTextCompilesAgainWithGlslang) {
  std::string log;
  EXPECT_TRUE(GlslangAccepts(Report().cross_compiled, log)) << log << "\n"
                                                            << Report().cross_compiled;
}

TEST_F(ToolchainProbeTest, GlslangCheckRejectsBrokenText) {
  // Guards the helper above: it must be able to fail, or the previous test proves nothing.
  std::string broken = Report().cross_compiled;
  broken += "\nvoid extra() { vec3 v = 1.0; }\n";
  std::string log;
  EXPECT_FALSE(GlslangAccepts(broken, log));
  EXPECT_NE(log.find("cannot convert"), std::string::npos) << log;
}

TEST_F(ToolchainProbeTest, OsMesaUsesASoftwareRasterizer) {
  const std::string& renderer = Report().osmesa_renderer;
  EXPECT_TRUE(renderer.find("llvmpipe") != std::string::npos ||
              renderer.find("softpipe") != std::string::npos)
      << "renderer: '" << renderer << "'";
}

TEST_F(ToolchainProbeTest, OsMesaContextIsCoreProfile33OrNewer) {
  // The probe asks for a 3.3 core context; Mesa reports e.g. "4.5 (Core Profile) Mesa 22.3.6".
  const std::string& version = Report().osmesa_version;
  ASSERT_GE(version.size(), 3u) << version;
  const int major = version[0] - '0';
  const int minor = version[2] - '0';
  EXPECT_TRUE(major > 3 || (major == 3 && minor >= 3)) << version;
  EXPECT_NE(version.find("Mesa"), std::string::npos) << version;
}

TEST_F(ToolchainProbeTest, ProbingTwiceGivesTheSameAnswer) {
  // glslang's process state and OSMesa contexts must survive repeated use.
  const ToolchainReport again = ProbeToolchain();
  EXPECT_EQ(again.error, "");
  EXPECT_EQ(again.spirv_words, Report().spirv_words);
  EXPECT_EQ(again.cross_compiled, Report().cross_compiled);
  EXPECT_EQ(again.osmesa_renderer, Report().osmesa_renderer);
}

}  // namespace
}  // namespace shaderport::toolchain
