// The three.js ShaderMaterial dialect (rules/dialects/threejs-shadermaterial.toml): the
// worked example of docs/architecture.md, "Adding a harness dialect". three.js compiles
// GLSL ES 1.00-style fragment code as GLSL ES 3.00 behind #defines (WebGLProgram.js), so
// a word GLSL ES 3.00 reserves fails there although plain WebGL 1 takes it; Chromium 156,
// given the code behind three.js' prefix, says "'sample' : Illegal use of reserved word".
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_test_util.h"
#include "scratch_dir.h"

namespace shaderport::testing {
namespace {

constexpr const char* kMaterial =
    "uniform float time;\n"
    "uniform sampler2D map;\n"
    "varying vec2 vUv;\n"
    "void main() {\n"
    "  vec4 texel = texture2D(map, vUv);\n"
    "  gl_FragColor = vec4(texel.rgb * (0.5 + 0.5 * sin(time)), 1.0) +\n"
    "                 vec4(cameraPosition * 0.0, 0.0);\n"
    "}\n";

TEST(ThreejsDialect, ChecksTheCodeAsThreejsCompilesIt) {
  const std::filesystem::path dir = ScratchDir("threejs-dialect");
  std::ofstream(dir / "material.frag") << kMaterial;
  std::ofstream(dir / "reserved.frag") << "varying vec2 vUv;\nvoid main() {\n"
                                          "  float sample = vUv.x;\n"
                                          "  gl_FragColor = vec4(sample);\n}\n";
  const CommandResult good =
      RunShaderport("check --no-config --no-cache --dialect threejs material.frag", dir);
  EXPECT_EQ(good.exit_code, 0) << good.out << good.err;
  const CommandResult reserved =
      RunShaderport("check --no-config --no-cache --dialect threejs reserved.frag", dir);
  EXPECT_EQ(reserved.exit_code, 1) << reserved.out;
  EXPECT_NE(reserved.out.find("reserved.frag:3:"), std::string::npos) << reserved.out;
}

// `port` writes WebGL2 of it: three.js' uniforms the code uses, its own output for
// gl_FragColor, and none of the #defines that only map GLSL ES 1.00 words.
TEST(ThreejsDialect, PortWritesStandaloneWebgl2) {
  const std::filesystem::path dir = ScratchDir("threejs-dialect-port");
  std::ofstream(dir / "material.frag") << kMaterial;
  const CommandResult ported =
      RunShaderport("port --no-config --dialect threejs material.frag -o ported.frag", dir);
  ASSERT_EQ(ported.exit_code, 0) << ported.out << ported.err;
  std::ifstream in(dir / "ported.frag");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("uniform highp vec3 cameraPosition;"), std::string::npos) << text;
  EXPECT_NE(text.find("out highp vec4 fragColor;"), std::string::npos) << text;
  EXPECT_EQ(text.find("pc_fragColor"), std::string::npos) << text;
  EXPECT_EQ(text.find("#define varying"), std::string::npos) << text;
  EXPECT_NE(text.find("texture(map, vUv)"), std::string::npos) << text;
  const CommandResult again =
      RunShaderport("check --no-config --no-cache --dialect webgl2 ported.frag", dir);
  EXPECT_EQ(again.exit_code, 0) << again.out << text;
}

}  // namespace
}  // namespace shaderport::testing
