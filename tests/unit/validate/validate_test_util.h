// Helpers shared by the validate tests.
#pragma once

#include <string>

#include "source/source_manager.h"
#include "validate/glslang_validator.h"

namespace shaderport::validate::testing {

// Validates one user file as is (WebGL: compile only).
inline ValidationResult ValidateText(SourceManager& sources, const std::string& text,
                                     model::Stage stage = model::Stage::kFragment,
                                     int default_version = 100) {
  const SourceFile& file = sources.Add("user.frag", text);
  ValidationRequest request;
  request.parts.push_back({file.Name(), file.Text(), file.Id(), PartKind::kUser});
  request.stage = stage;
  request.default_version = default_version;
  return ValidateWithGlslang(request);
}

inline LineColumn Where(const SourceManager& sources, const SourceRange& range) {
  return sources.Get(range.file).LocationOf(range.begin);
}

}  // namespace shaderport::validate::testing
