// TypeMismatch records: the strict-typing mistakes later rules fix, and none on correct code.
#include <gtest/gtest.h>

#include "sema_test_util.h"

namespace shaderport::glsl {
namespace {

using testing::AnalyzeText;

std::unique_ptr<testing::Analyzed> Body(const std::string& body) {
  return AnalyzeText(
      "#version 300 es\nprecision highp float;\nuniform float x;\n"
      "uniform vec3 v;\nuniform int n;\nfloat f(float a) { return a; }\n" +
      body + "\n");
}

struct Expected {
  const char* text;
  MismatchKind kind;
  MismatchContext context;
  const char* required;
  const char* actual;
};

void ExpectMismatches(const std::string& body, std::initializer_list<Expected> expected) {
  auto a = Body(body);
  ASSERT_EQ(a->model.mismatches.size(), expected.size()) << body;
  size_t k = 0;
  for (const Expected& e : expected) {
    const TypeMismatch& m = a->model.mismatches[k++];
    EXPECT_EQ(a->TextOf(m.node), e.text) << body;
    EXPECT_EQ(m.kind, e.kind) << body;
    EXPECT_EQ(m.context, e.context) << body;
    EXPECT_EQ(a->model.Spell(m.required), e.required) << body;
    EXPECT_EQ(a->model.Spell(m.actual), e.actual) << body;
  }
}

constexpr auto kInt = MismatchKind::kIntForFloat;
constexpr auto kScalar = MismatchKind::kScalarForVector;

TEST(MismatchTest, ScalarInitializingVector) {
  ExpectMismatches("void main() { vec3 c = 1.0; }",
                   {{"1.0", kScalar, MismatchContext::kInitializer, "vec3", "float"}});
  ExpectMismatches("void main() { vec3 c; c = x; }",
                   {{"x", kScalar, MismatchContext::kAssignment, "vec3", "float"}});
  ExpectMismatches("void main() { vec2 c = 0; }",
                   {{"0", kScalar, MismatchContext::kInitializer, "vec2", "int"}});
}

TEST(MismatchTest, IntWhereFloatIsRequired) {
  ExpectMismatches("void main() { float y = 1; }",
                   {{"1", kInt, MismatchContext::kInitializer, "float", "int"}});
  ExpectMismatches("void main() { float y = pow(x, 2); }",
                   {{"2", kInt, MismatchContext::kBuiltinCallArgument, "float", "int"}});
  ExpectMismatches("void main() { float y = x * 2; }",
                   {{"2", kInt, MismatchContext::kBinaryOperand, "float", "int"}});
  ExpectMismatches("void main() { vec3 c = 2 * v; }",
                   {{"2", kInt, MismatchContext::kBinaryOperand, "float", "int"}});
  ExpectMismatches("float g() { return 1; }",
                   {{"1", kInt, MismatchContext::kReturn, "float", "int"}});
  ExpectMismatches("void main() { float y = f(1); }",
                   {{"1", kInt, MismatchContext::kCallArgument, "float", "int"}});
  ExpectMismatches("void main() { float y; y = n; y += 1; }",
                   {{"n", kInt, MismatchContext::kAssignment, "float", "int"},
                    {"1", kInt, MismatchContext::kAssignment, "float", "int"}});
  ExpectMismatches("void main() { float y = x > 0.0 ? 1 : 2.0; }",
                   {{"1", kInt, MismatchContext::kTernaryBranch, "float", "int"}});
  ExpectMismatches("void main() { vec3 c = mix(v, v, 0); }",
                   {{"0", kInt, MismatchContext::kBuiltinCallArgument, "float", "int"}});
  ExpectMismatches("void main() { vec2 c = vec2(x) + ivec2(1); }",
                   {{"ivec2(1)", kInt, MismatchContext::kBinaryOperand, "vec2", "ivec2"}});
  ExpectMismatches("void main() { bool b = x < 1; }",
                   {{"1", kInt, MismatchContext::kBinaryOperand, "float", "int"}});
}

TEST(MismatchTest, NoneOnCorrectCode) {
  ExpectMismatches(R"(
struct S { float a; vec2 b; };
void main() {
  vec3 c = vec3(1);              // constructors convert
  vec4 d = vec4(v, 1);
  float y = float(n) * 2.0;
  int k = n * 2;
  ivec2 iv = ivec2(1, 2) + 3;
  S s = S(1.0, vec2(0));
  float z = pow(x, 2.0) + f(y) + s.a;
  c *= 2.0;
  c = c * mat3(1.0);
  for (int i = 0; i < 10; ++i) { z += float(i); }
  bool b = z > 0.0 ? true : false;
  uint u = uint(k) >> 1u;
  float w[2] = float[2](1.0, 2.0);
})",
                   {});
}

TEST(MismatchTest, NoneWhenTypesAreUnknown) {
  ExpectMismatches("void main() { float y = undeclared; vec3 c = undeclared2 * 2; }", {});
}

}  // namespace
}  // namespace shaderport::glsl
