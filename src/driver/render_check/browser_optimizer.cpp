#include "driver/render_check/browser_optimizer.h"

#include "base/large_stack.h"
#include "base/limits.h"
#include "diag/diagnostic.h"
#include "driver/tree_depth.h"
#include "source/source_manager.h"
#include "toolchain/cross_compile.h"
#include "toolchain/inlined_size.h"
#include "toolchain/spirv_compile.h"
#include "toolchain/spirv_tools.h"

namespace shaderport::driver {

std::optional<std::string> OptimizeAsBrowser(std::string_view text) {
  std::optional<std::string> optimized;
  // glslang's SPIR-V generator recurses once per level of the tree.
  if (SyntaxTreeDepth(text) > limits::kMaxSpirvTreeDepth) return optimized;
  // glslang and SPIRV-Cross recurse over the tree: deep expressions need the large stack.
  RunOnLongLivedLargeStack([&] {
    SourceManager local;
    const SourceFile& file = local.Add("<render>", std::string(text), true);
    toolchain::SpirvCompilation compiled = toolchain::CompileToSpirv(file, model::Stage::kFragment);
    if (HasErrors(compiled.diagnostics) || compiled.words.empty()) return;
    // spirv-opt inlines every call first; past the limit that alone takes seconds.
    if (toolchain::InlinedInstructionCount(compiled.words) > limits::kMaxInlinedInstructions) {
      return;
    }
    toolchain::OptimizeOutcome outcome =
        toolchain::OptimizeSpirv(compiled.words, toolchain::OptimizeLevel::kPerformance);
    if (outcome.words.empty()) return;
    toolchain::CrossOutcome crossed =
        toolchain::CrossCompile(outcome.words, toolchain::CrossTarget::kEssl300, {});
    if (crossed.text.empty()) return;
    optimized = std::move(crossed.text);
  });
  return optimized;
}

}  // namespace shaderport::driver
