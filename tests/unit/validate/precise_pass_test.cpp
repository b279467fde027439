#include "validate/precise_pass.h"

#include <glslang/Include/intermediate.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <gtest/gtest.h>

#include <array>
#include <string_view>

#include "validate/glslang_runner.h"

namespace shaderport::validate {
namespace {

TEST(PrecisePassTest, OnlyTextsThatCannotFormTheKeywordSkipIt) {
  EXPECT_TRUE(CannotSpellPrecise("void main() { float x = a * b; }"));
  EXPECT_TRUE(CannotSpellPrecise(""));
  EXPECT_FALSE(CannotSpellPrecise("precise float x;"));
  EXPECT_FALSE(CannotSpellPrecise("// a precise comment"));  // comments are not told apart
  // Other words that contain it cannot become the keyword.
  EXPECT_TRUE(CannotSpellPrecise("// imprecise comment"));
  EXPECT_TRUE(CannotSpellPrecise("float precise_x = precise2;"));
  // A digit before it ends a number: "1precise" scans as 1 and precise.
  EXPECT_FALSE(CannotSpellPrecise("x = 1precise;"));
  EXPECT_FALSE(CannotSpellPrecise("(precise)"));
  // Token pasting and line continuations can assemble the word from pieces.
  EXPECT_FALSE(CannotSpellPrecise("#define P(a, b) a##b\nP(pre, cise) float x;"));
  EXPECT_FALSE(CannotSpellPrecise("pre\\\ncise float x;"));
  EXPECT_FALSE(CannotSpellPrecise("pre\\\r\ncise float x;"));
  EXPECT_FALSE(CannotSpellPrecise("x\\\n precise float y;"));
  // Continued lines that do not form it: a multi-line macro.
  EXPECT_TRUE(CannotSpellPrecise("#define F(x) \\\n  (x * 2.0)\nfloat y = F(1.0);"));
  EXPECT_TRUE(CannotSpellPrecise("im\\\nprecise"));
}

constexpr std::string_view kPlain =
    "#version 300 es\nprecision highp float;\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n";

TEST(PrecisePassTest, ValidationSkipsThePassForATextWithoutTheKeyword) {
  if (!PrecisePassCanBeSkipped()) GTEST_SKIP() << "this build runs glslang's pass unwrapped";
  const uint64_t before = PrecisePassesSkipped();
  const std::array<GlslangPart, 1> plain = {GlslangPart{"p0", kPlain}};
  EXPECT_TRUE(RunGlslang(plain, model::Stage::kFragment, 100, true).compiled);
  EXPECT_EQ(PrecisePassesSkipped(), before + 1);

  const std::string commented = std::string(kPlain) + "// precise\n";
  const std::array<GlslangPart, 1> mention = {GlslangPart{"p0", commented}};
  EXPECT_TRUE(RunGlslang(mention, model::Stage::kFragment, 100, true).compiled);
  EXPECT_EQ(PrecisePassesSkipped(), before + 1);
}

// Finds an arithmetic node that glslang's pass marked noContraction.
class NoContractionFinder : public glslang::TIntermTraverser {
 public:
  bool visitBinary(glslang::TVisit, glslang::TIntermBinary* node) override {
    if (node->getOp() == glslang::EOpMul && node->getType().getQualifier().isNoContraction()) {
      found = true;
    }
    return true;
  }
  bool found = false;
};

bool MultiplyIsMarkedNoContraction(std::string_view text) {
  InitializeGlslangOnce();
  glslang::TShader shader(EShLangFragment);
  const char* strings[] = {text.data()};
  const int lengths[] = {static_cast<int>(text.size())};
  shader.setStringsWithLengths(strings, lengths, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, EShLangFragment, glslang::EShClientNone, 0);
  shader.setEnvClient(glslang::EShClientNone, static_cast<glslang::EShTargetClientVersion>(0));
  shader.setEnvTarget(glslang::EShTargetNone, static_cast<glslang::EShTargetLanguageVersion>(0));
  const std::array<std::string_view, 1> texts = {text};
  const PrecisePassSkip skip(texts);
  EXPECT_TRUE(shader.parse(GetDefaultResources(), 100, false, EShMsgDefault))
      << shader.getInfoLog();
  NoContractionFinder finder;
  shader.getIntermediate()->getTreeRoot()->traverse(&finder);
  return finder.found;
}

TEST(PrecisePassTest, APreciseShaderStillGetsGlslangsPass) {
  // `a * b` is marked only by the pass, which follows `precise` from x backwards.
  EXPECT_TRUE(MultiplyIsMarkedNoContraction(
      "#version 320 es\nprecision highp float;\nin float a;\nin float b;\nout vec4 o;\n"
      "void main() { precise float x = a * b + a; o = vec4(x); }\n"));
  EXPECT_FALSE(MultiplyIsMarkedNoContraction(
      "#version 320 es\nprecision highp float;\nin float a;\nin float b;\nout vec4 o;\n"
      "void main() { float x = a * b + a; o = vec4(x); }\n"));
}

}  // namespace
}  // namespace shaderport::validate
