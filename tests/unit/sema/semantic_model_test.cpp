#include "glsl/sema/semantic_model.h"

#include <gtest/gtest.h>

#include "sema_test_util.h"

namespace shaderport::glsl {
namespace {

using testing::AnalyzeText;

constexpr const char* kDeclarations = R"(#version 300 es
precision highp float;
uniform vec3 v3;
uniform vec2 v2;
uniform mat3 m3;
uniform mat2x3 m23;
uniform float f;
uniform int i;
uniform uint u;
uniform ivec2 iv;
uniform bvec3 bv;
uniform sampler2D s;
uniform isampler3D is3;
uniform samplerCubeShadow scs;
struct S { vec2 p; float a[3]; };
uniform S st;
const int N = 4;
float arr[N];
vec3 g(vec3 x) { return x; }
float g(float x) { return x; }
out vec4 color;
void main() {
)";

struct Case {
  const char* expr;
  const char* type;
};

void ExpectTypes(const std::string& body, std::initializer_list<Case> cases, int version = 300) {
  std::string text = std::string(kDeclarations) + body + "\n}\n";
  auto a = AnalyzeText(text, version);
  for (const Case& c : cases) EXPECT_EQ(a->TypeOf(c.expr), c.type) << c.expr;
}

TEST(SemanticModelTest, OperandsAndAccess) {
  ExpectTypes(R"(
  v3.xy; v3.x; v3.bgr; v2.stst; st.p; st.a; st.a[1]; m3[0]; v3[1]; arr; arr[2];
  1; 1u; 1.5; true; (v3); gl_FragCoord.xy; st.a.length(); N;)",
              {{"v3.xy", "vec2"},
               {"v3.x", "float"},
               {"v3.bgr", "vec3"},
               {"v2.stst", "vec4"},
               {"st.p", "vec2"},
               {"st.a", "float[3]"},
               {"st.a[1]", "float"},
               {"m3[0]", "vec3"},
               {"v3[1]", "float"},
               {"arr", "float[4]"},
               {"arr[2]", "float"},
               {"1", "int"},
               {"1u", "uint"},
               {"1.5", "float"},
               {"true", "bool"},
               {"(v3)", "vec3"},
               {"gl_FragCoord.xy", "vec2"},
               {"st.a.length()", "int"},
               {"N", "int"}});
}

TEST(SemanticModelTest, BadSwizzlesAreUnknown) {
  ExpectTypes("v2.z; v3.xg; v3.xyzwx; f.x; st.q;", {{"v2.z", "unknown"},
                                                    {"v3.xg", "unknown"},
                                                    {"v3.xyzwx", "unknown"},
                                                    {"f.x", "unknown"},
                                                    {"st.q", "unknown"}});
}

TEST(SemanticModelTest, ArithmeticOperators) {
  ExpectTypes(R"(
  m3 * v3; v3 * m3; m23 * v2; v3 * m23; f * v3; v3 * f; m3 * m3; m23 * mat2(1.0); v3 + v3;
  v3 - f; f / v3; i % 2; iv % 2; i << 1; iv >> 1; u & 3u; -v3; +f; ~i; v3 * v2; f * i;)",
              {{"m3 * v3", "vec3"},
               {"v3 * m3", "vec3"},
               {"m23 * v2", "vec3"},
               {"v3 * m23", "vec2"},
               {"f * v3", "vec3"},
               {"v3 * f", "vec3"},
               {"m3 * m3", "mat3"},
               {"m23 * mat2(1.0)", "mat2x3"},
               {"v3 + v3", "vec3"},
               {"v3 - f", "vec3"},
               {"f / v3", "vec3"},
               {"i % 2", "int"},
               {"iv % 2", "ivec2"},
               {"i << 1", "int"},
               {"iv >> 1", "ivec2"},
               {"u & 3u", "uint"},
               {"-v3", "vec3"},
               {"+f", "float"},
               {"~i", "int"},
               {"v3 * v2", "unknown"},
               // int beside float: typed as float, and recorded as a mismatch
               {"f * i", "float"}});
}

TEST(SemanticModelTest, ComparisonLogicalAndOthers) {
  ExpectTypes(R"(
  f < 1.0; i >= 2; v3 == v3; st == st; !bv.x; bv.x && true; bv.y ^^ false; f > 0.0 ? v3 : v3;
  f = 2.0; i += 1; f, i; u < 1u; v3 < v3;)",
              {{"f < 1.0", "bool"},
               {"i >= 2", "bool"},
               {"v3 == v3", "bool"},
               {"st == st", "bool"},
               {"!bv.x", "bool"},
               {"bv.x && true", "bool"},
               {"bv.y ^^ false", "bool"},
               {"f > 0.0 ? v3 : v3", "vec3"},
               {"f = 2.0", "float"},
               {"i += 1", "int"},
               {"f, i", "int"},
               {"u < 1u", "bool"},
               {"v3 < v3", "unknown"}});
}

TEST(SemanticModelTest, ConstructorsAndCalls) {
  ExpectTypes(R"(
  vec3(1); mat2x3(1.0); float[3](1.0, 2.0, 3.0); float[](1.0, 2.0); S(v2, float[3](1.0, 2.0, 3.0));
  g(v3); g(f); g(v2); texture(s, v2); texture(is3, v3); texture(scs, vec4(1.0));
  textureSize(s, 0); texelFetch(s, iv, 0); dot(v3, v3); cross(v3, v3); mix(v3, v3, f);
  mix(v3, v3, bv); clamp(i, 0, 1); min(u, 2u); length(v2); inverse(m3); transpose(m23);
  outerProduct(v3, v2); determinant(m3); lessThan(v3, v3); any(bv); floatBitsToInt(v2);
  packHalf2x16(v2); isnan(f); step(0.5, v3); smoothstep(0.0, 1.0, v2); matrixCompMult(m23, m23);
  dFdx(v2); fwidth(f); round(f); sinh(v3); pow(v3, v3); atan(f, f); atan(f); notdefined(1.0);)",
              {{"vec3(1)", "vec3"},
               {"mat2x3(1.0)", "mat2x3"},
               {"float[3](1.0, 2.0, 3.0)", "float[3]"},
               {"float[](1.0, 2.0)", "float[2]"},
               {"S(v2, float[3](1.0, 2.0, 3.0))", "S"},
               {"g(v3)", "vec3"},
               {"g(f)", "float"},
               {"g(v2)", "unknown"},
               {"texture(s, v2)", "vec4"},
               {"texture(is3, v3)", "ivec4"},
               {"texture(scs, vec4(1.0))", "float"},
               {"textureSize(s, 0)", "ivec2"},
               {"texelFetch(s, iv, 0)", "vec4"},
               {"dot(v3, v3)", "float"},
               {"cross(v3, v3)", "vec3"},
               {"mix(v3, v3, f)", "vec3"},
               {"mix(v3, v3, bv)", "vec3"},
               {"clamp(i, 0, 1)", "int"},
               {"min(u, 2u)", "uint"},
               {"length(v2)", "float"},
               {"inverse(m3)", "mat3"},
               {"transpose(m23)", "mat3x2"},
               {"outerProduct(v3, v2)", "mat2x3"},
               {"determinant(m3)", "float"},
               {"lessThan(v3, v3)", "bvec3"},
               {"any(bv)", "bool"},
               {"floatBitsToInt(v2)", "ivec2"},
               {"packHalf2x16(v2)", "uint"},
               {"isnan(f)", "bool"},
               {"step(0.5, v3)", "vec3"},
               {"smoothstep(0.0, 1.0, v2)", "vec2"},
               {"matrixCompMult(m23, m23)", "mat2x3"},
               {"dFdx(v2)", "vec2"},
               {"fwidth(f)", "float"},
               {"round(f)", "float"},
               {"sinh(v3)", "vec3"},
               {"pow(v3, v3)", "vec3"},
               {"atan(f, f)", "float"},
               {"atan(f)", "float"},
               {"notdefined(1.0)", "unknown"}});
}

TEST(SemanticModelTest, Essl100BuiltIns) {
  auto a = AnalyzeText(R"(
precision mediump float;
uniform sampler2D s;
uniform samplerCube c;
varying vec2 uv;
void main() {
  gl_FragColor = texture2D(s, uv) + textureCube(c, vec3(uv, 1.0)) + texture2DProj(s, vec3(uv, 1.0));
  gl_FragData[0] = vec4(float(gl_MaxDrawBuffers));
}
)",
                       100);
  EXPECT_EQ(a->TypeOf("texture2D(s, uv)"), "vec4");
  EXPECT_EQ(a->TypeOf("textureCube(c, vec3(uv, 1.0))"), "vec4");
  EXPECT_EQ(a->TypeOf("gl_FragColor"), "vec4");
  EXPECT_EQ(a->TypeOf("gl_FragData[0]"), "vec4");
  EXPECT_EQ(a->TypeOf("gl_MaxDrawBuffers"), "int");
  EXPECT_TRUE(a->model.mismatches.empty());
}

TEST(SemanticModelTest, ScopesSymbolsAndUses) {
  auto a = AnalyzeText(R"(#version 300 es
precision highp float;
float x = 1.0;
float f(float y) { return y * x; }
out vec4 o;
void main() {
  float x = 2.0;
  { int x = 3; x += 1; }
  o = vec4(f(x));
}
)");
  const SemanticModel& m = a->model;
  std::vector<uint32_t> xs = m.FindSymbols("x");
  ASSERT_EQ(xs.size(), 3u);
  EXPECT_EQ(m.Spell(m.symbols[xs[2]].type), "int");
  EXPECT_EQ(m.UsesOf(xs[0]).size(), 1u);  // y * x in f
  EXPECT_EQ(m.UsesOf(xs[1]).size(), 1u);  // f(x) in main
  EXPECT_EQ(m.UsesOf(xs[2]).size(), 1u);  // x += 1
  std::vector<uint32_t> fs = m.FindSymbols("f");
  ASSERT_EQ(fs.size(), 1u);
  EXPECT_EQ(m.symbols[fs[0]].kind, SymbolKind::kFunction);
  EXPECT_EQ(m.UsesOf(fs[0]).size(), 1u);
  std::vector<uint32_t> ys = m.FindSymbols("y");
  ASSERT_EQ(ys.size(), 1u);
  EXPECT_EQ(m.symbols[ys[0]].kind, SymbolKind::kParameter);
  std::vector<uint32_t> vec4s = m.FindSymbols("vec4");
  EXPECT_TRUE(vec4s.empty());
  EXPECT_TRUE(m.mismatches.empty());
  EXPECT_GE(m.scopes.size(), 3u);
}

TEST(SemanticModelTest, PredeclaredPairsAndHeader) {
  AnalyzeOptions options;
  options.predeclared = testing::ShaderToyUniforms();
  auto header = AnalyzeText(std::vector<std::string>{"uniform vec2 uExtra; struct P { int k; };"},
                            AnalyzeOptions{});
  options.header = &header->parse.tree;
  auto a = AnalyzeText(std::vector<std::string>{R"(
void mainImage(out vec4 c, in vec2 p) {
  vec2 uv = p / iResolution.xy;
  P q = P(1);
  c = texture(iChannel0, uv) * iTime + vec4(uExtra, float(q.k), iChannelTime[1]);
}
)"},
                       options);
  EXPECT_EQ(a->TypeOf("p / iResolution.xy"), "vec2");
  EXPECT_EQ(a->TypeOf("texture(iChannel0, uv) * iTime"), "vec4");
  EXPECT_EQ(a->TypeOf("uExtra"), "vec2");
  EXPECT_EQ(a->TypeOf("q.k"), "int");
  EXPECT_EQ(a->TypeOf("iChannelTime[1]"), "float");
  uint32_t time = a->model.FindSymbols("iTime").front();
  EXPECT_TRUE(a->model.symbols[time].predeclared);
  EXPECT_EQ(a->model.UsesOf(time).size(), 1u);
  EXPECT_TRUE(a->model.mismatches.empty());
}

TEST(SemanticModelTest, LongOperatorChainsDoNotExhaustTheStack) {
  std::string sum = "1.0";
  for (int k = 0; k < 50000; ++k) sum += "+1.0";
  auto a = AnalyzeText("#version 300 es\nprecision highp float;\nfloat x = " + sum + ";\n");
  EXPECT_EQ(a->TypeOf(sum), "float");
}

}  // namespace
}  // namespace shaderport::glsl
