// Detecting the harness a shader was written for from its entry point and the
// names it uses without declaring them.
#include <gtest/gtest.h>

#include <filesystem>

#include "rule/harness_dialect_detect.h"
#include "shadertoy_test_support.h"

namespace shaderport::rule {
namespace {

std::string Detected(std::string_view text) {
  const auto match = DetectDialectInText(model::BuiltinDialects(), text);
  return match ? match->dialect->name : "none";
}

std::string Corpus(const std::string& path) {
  return shaderport::testing::ReadWholeFile(std::filesystem::path(SHADERPORT_SOURCE_DIR) /
                                            "corpus" / path);
}

TEST(DialectDetect, EntryPointMeansShaderToy) {
  EXPECT_EQ(Detected("void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }"), "shadertoy");
  EXPECT_EQ(Detected("vec2 mainSound(int s, float t) { return vec2(0.0); }"), "shadertoy");
  // With a main() of its own it is not ShaderToy code.
  EXPECT_EQ(Detected("void mainImage(out vec4 c, in vec2 p) {}\nvoid main() {}"), "none");
}

TEST(DialectDetect, FreeNamesPickTheHarness) {
  EXPECT_EQ(Detected("void main() { color = vec4(uv, sin(time), 1.0); }"), "raymarch-blog");
  EXPECT_EQ(Detected("uniform float time;\nuniform vec2 resolution;\n"
                     "void main() { gl_FragColor = vec4(surfacePosition, time, 1.0); }"),
            "glslsandbox");
  EXPECT_EQ(Detected("void main() { gl_FragColor = vec4(gl_FragCoord.xy / u_resolution, "
                     "u_time, 1.0); }"),
            "bookofshaders");
  EXPECT_EQ(Detected("float f() { return iGlobalTime; }"), "shadertoy");
}

TEST(DialectDetect, PlainWebGLIsNoHarness) {
  EXPECT_EQ(Detected("uniform float time;\nvoid main() { gl_FragColor = vec4(time); }"), "none");
  EXPECT_EQ(Detected(""), "none");
  EXPECT_EQ(Detected("}}}{{{ garbage ((("), "none");
}

TEST(DialectDetect, Corpus) {
  for (const char* path : {"ao/template.glsl", "ao/variant-fibonacci.glsl",
                           "strict-typing/control-explicit-conversions.glsl"}) {
    EXPECT_EQ(Detected(Corpus(path)), "shadertoy") << path;
  }
  for (const char* path :
       {"raymarch/stage1-basic-scene.glsl", "raymarch/stage2-ambient-occlusion.glsl",
        "raymarch/stage3-brighter.glsl", "raymarch/stage4-shadows.glsl"}) {
    EXPECT_EQ(Detected(Corpus(path)), "raymarch-blog") << path;
  }
  for (const char* path : {"ssao/ssao.frag", "ssao/blend.frag", "ssao/lighting.vert"}) {
    EXPECT_EQ(Detected(Corpus(path)), "none") << path;
  }
}

TEST(DialectDetect, EvidenceExplainsTheChoice) {
  const auto match =
      DetectDialectInText(model::BuiltinDialects(), "void main() { color = vec4(uv, 0.0, 1.0); }");
  ASSERT_TRUE(match);
  EXPECT_EQ(match->score, 6);
  EXPECT_EQ(match->evidence, (std::vector<std::string>{"uses uv without declaring it",
                                                       "uses color without declaring it"}));
}

}  // namespace
}  // namespace shaderport::rule
