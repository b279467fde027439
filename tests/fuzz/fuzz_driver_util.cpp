#include "fuzz_driver_util.h"

#include <algorithm>
#include <string>

#include "validate/glslang_validator.h"
#include "validate/shadertoy_contract.h"

namespace shaderport::fuzz {

size_t ValidationErrors(std::string_view text, const driver::DetectedKind& kind, bool as_output,
                        SourceManager& sources) {
  const SourceFile& file = sources.Add("fuzz-validate.glsl", std::string(text));
  validate::ValidationRequest request;
  if (!as_output && kind.dialect == driver::Dialect::kShaderToy) {
    const bool is_common = kind.pass == model::PassKind::kCommon;
    request = validate::ComposeShaderToyRequest(sources, kind.pass, {}, nullptr, file);
    if (is_common) request.link = false;
  } else {
    request.parts.push_back({file.Name(), file.Text(), file.Id()});
    request.stage = kind.stage;
    request.default_version = 100;
  }
  const DiagnosticList diagnostics = validate::ValidateWithGlslang(request).diagnostics;
  return static_cast<size_t>(std::count_if(diagnostics.begin(), diagnostics.end(),
                                           [](auto& d) { return d.severity == Severity::kError; }));
}

bool RangeInside(const SourceManager& sources, const SourceRange& range) {
  if (!range.Valid()) return true;
  if (range.file >= sources.Size()) return false;
  return range.begin <= range.end && range.end <= sources.Get(range.file).Text().size();
}

}  // namespace shaderport::fuzz
