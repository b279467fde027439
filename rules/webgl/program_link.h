// WebGL's link rules for a vertex + fragment program, on our own trees: the
// stages must be of one GLSL ES version; the interface they share must agree
// (varyings: type, presence, ES 1.00 invariance; uniforms and uniform blocks: type and
// precision, a struct's members too); the varyings must fit the context's varying
// vectors by GLSL ES 1.00 Appendix A.7 packing, each stage's used uniforms its uniform
// vectors as Chromium counts them.
#pragma once

#include "diag/diagnostic.h"
#include "glsl/lex/preprocessor.h"
#include "glsl/sema/semantic_model.h"
#include "glsl/syntax/ast.h"

namespace shaderport::rules {

struct LinkStage {
  const glsl::SyntaxTree* tree = nullptr;
  const glsl::SemanticModel* model = nullptr;
  const glsl::PreprocessResult* preprocessed = nullptr;
  int version = 100;
};

struct LinkLimits {
  // Chromium's limits as the conformance cases were sized (WebGL requires at least 8).
  int max_varying_vectors = 31;
  int max_vertex_uniform_vectors = 4096;  // Chromium 156 on SwiftShader
  int max_fragment_uniform_vectors = 4096;
};

// Errors of rule ids link/version, link/varying, link/uniform,
// link/invariant, link/varying-packing and link/uniform-vectors, placed on the
// declarations in either stage.
DiagnosticList CheckProgramLink(const LinkStage& vertex, const LinkStage& fragment,
                                const LinkLimits& limits = {});

}  // namespace shaderport::rules
