// The inlined size of an entry point, counted from the call graph, grows with every
// call site as inlining does.
#include "toolchain/inlined_size.h"

#include <gtest/gtest.h>

#include <string>

#include "source/source_manager.h"
#include "toolchain/spirv_compile.h"

namespace shaderport::toolchain {
namespace {

SpirvWords Compile(const std::string& body) {
  SourceManager sources;
  const SourceFile& file = sources.Add(
      "inlined.frag",
      "#version 300 es\nprecision highp float;\nuniform float u;\nout vec4 o;\n" + body, true);
  SpirvCompilation compiled = CompileToSpirv(file, model::Stage::kFragment);
  EXPECT_FALSE(HasErrors(compiled.diagnostics));
  return compiled.words;
}

TEST(InlinedSize, EveryCallSiteCountsItsCalleeAgain) {
  const std::string leaf = "float f(float x) { return sin(x) * x + cos(x * 2.0) / (x + 1.0); }\n";
  const uint64_t once = InlinedInstructionCount(
      Compile(leaf + "float g(float x) { return f(x); }\nvoid main() { o = vec4(g(u)); }\n"));
  const uint64_t nine = InlinedInstructionCount(
      Compile(leaf + "float g(float x) { return f(x) + f(x + 1.0) + f(x + 2.0); }\n"
                     "void main() { o = vec4(g(u) + g(u * 2.0) + g(u * 3.0)); }\n"));
  ASSERT_GT(once, 0U);
  // f's body (about a dozen instructions) is counted 9 times instead of once.
  EXPECT_GT(nine, once + 8 * 10);
}

TEST(InlinedSize, ModulesWithoutAnEntryPointOrMalformedCountNothing) {
  EXPECT_EQ(InlinedInstructionCount({}), 0U);
  SpirvWords words = Compile("void main() { o = vec4(u); }\n");
  ASSERT_GT(words.size(), 5U);
  words.resize(7);  // cut inside the first instruction
  EXPECT_EQ(InlinedInstructionCount(words), 0U);
}

}  // namespace
}  // namespace shaderport::toolchain
