// Which expressions reach Chromium's GPU-less renderer as constants. Beyond the
// constant expressions ANGLE folds, SwiftShader optimises the SPIR-V it is given
// (inlining, SSA, constant propagation) and then folds built-in calls on constants
// with the C library (`sin(a)` after `float a = 0.3;` is the exact sin(0.3), not
// its polynomial) and divisions by constants into multiplications. Measured, not
// assumed: see cpu_browser_math.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include "glsl/sema/semantic_model.h"
#include "glsl/syntax/ast.h"

namespace shaderport::glsl {

class DriverFolding {
 public:
  // `parent`: by node id, kNoNode for the root.
  DriverFolding(const SyntaxTree& tree, const SemanticModel& model,
                const std::vector<uint32_t>& parent);

  // A constant expression, or one made of variables that are initialised with a
  // constant and never written, and of `in` parameters that every call passes a
  // constant.
  bool IsFolded(const Expr* expr) const;

 private:
  enum class State : uint8_t { kUnknown, kVisiting, kFolded, kNotFolded };

  bool IsFolded(const Expr* expr, int depth) const;
  bool SymbolIsFolded(uint32_t symbol, int depth) const;
  bool VariableIsFolded(const Symbol& symbol, uint32_t symbol_id, int depth) const;
  bool ParameterIsFolded(const Symbol& symbol, uint32_t symbol_id, int depth) const;
  bool IsWritten(uint32_t use) const;
  bool PassedForWriting(const CallExpr& call, const Node& argument) const;
  const Node* Parent(const Node& node) const;

  const SyntaxTree& tree_;
  const SemanticModel& model_;
  const std::vector<uint32_t>& parent_;
  std::vector<std::vector<uint32_t>> uses_;  // by symbol
  mutable std::vector<State> state_;         // by symbol
};

}  // namespace shaderport::glsl
