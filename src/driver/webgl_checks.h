// The WebGL layer of `check`: what a browser's compiler (ANGLE) rejects or warns
// about beyond glslang, and the glslang errors a browser does not raise.
// docs/browser-divergence.md lists every place where the two disagree.
#pragma once

#include <string>

#include "diag/diagnostic.h"
#include "driver/dialect.h"
#include "driver/front_end.h"
#include "rules/webgl/glslang_divergence.h"

namespace shaderport::driver {

struct WebglCheckSettings {
  model::Target target = model::Target::kWebGL2;
  model::EnabledExtensions extensions;  // --enabled-extensions
  model::Stage stage = model::Stage::kFragment;
  bool shadertoy = false;
  // The version a host forces on the code (FileDecision::ForcedVersion), 0: its own.
  int forced_version = 0;
  // The code is compiled behind text a host generates (ShaderToy's, a harness prelude).
  bool behind_header = false;
};

// Findings of the check and lint rules (rules/webgl/*, rules/portability/*) and of
// our front end's WebGL limits.
DiagnosticList RunWebglChecks(const SourceFile& file, const FrontEndResult& front,
                              const WebglCheckSettings& settings);

// Rewrites glslang's findings where glslang and the browser disagree: an error the
// browser does not raise becomes a note (or the browser's warning) that says why.
void AlignGlslangWithBrowser(const SourceFile& file, const FrontEndResult& front,
                             const WebglCheckSettings& settings,
                             DiagnosticList& glslang_diagnostics);

// The text of `part` (`file` itself, or `common`, ShaderToy's Common compiled with it) as
// glslang should see it where glslang and browsers differ on purpose
// (rules::TextForGlslang): its text is empty when glslang can compile it as it is.
rules::GlslangText TextForGlslang(const SourceFile& file, const SourceFile* common,
                                  const SourceFile& part, const FrontEndResult& front,
                                  const WebglCheckSettings& settings);

// `part` as our preprocessor expanded it (rules::ExpandedTextForGlslang): what glslang
// compiles when its own preprocessor crashed on the part's macros.
std::string ExpandedTextForGlslang(const SourceFile& file, const SourceFile& part,
                                   const FrontEndResult& front, const WebglCheckSettings& settings);

}  // namespace shaderport::driver
