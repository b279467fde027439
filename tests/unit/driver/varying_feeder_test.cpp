#include "driver/render_check/varying_feeder.h"

#include <gtest/gtest.h>

#include "validate/stage_link.h"

namespace shaderport::driver {
namespace {

TEST(VaryingFeederTest, FeedsEveryInputSoTheProgramLinks) {
  const std::string fragment =
      "#version 300 es\nprecision highp float;\n"
      "in vec2 vUv;\nsmooth in vec3 vNormal;\nin highp vec4 vColor;\nin float fog[2];\n"
      "flat in int id;\nout vec4 color;\n"
      "void main() { color = vec4(vUv, vNormal.z + fog[1], 1.0) * vColor + float(id); }\n";
  const std::string vertex = FeederVertexShader(fragment);
  ASSERT_FALSE(vertex.empty());
  EXPECT_NE(vertex.find("out highp vec2 vUv;"), std::string::npos) << vertex;
  EXPECT_NE(vertex.find("flat out highp int id;"), std::string::npos) << vertex;
  EXPECT_NE(vertex.find("vNormal = normalize("), std::string::npos) << vertex;
  const validate::StageLinkResult link = validate::LinkStages(vertex, fragment);
  EXPECT_TRUE(link.linked) << link.log << "\n" << vertex;
}

TEST(VaryingFeederTest, NoInputsNoShader) {
  EXPECT_EQ(FeederVertexShader("#version 300 es\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n"),
            "");
  // Inputs of functions are parameters, not stage inputs.
  EXPECT_EQ(FeederVertexShader("#version 300 es\nfloat f(in float x) { return x; }\n"), "");
}

}  // namespace
}  // namespace shaderport::driver
