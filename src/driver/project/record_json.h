// A project written back as one corpus-format record (what `render` draws from):
// {"id", "name", "author", "license", "passes": [{"type", "name", "code", "inputs"}]}.
#pragma once

#include <string>

#include "driver/project/shadertoy_project.h"

namespace shaderport::driver::project {

std::string ToRecordJson(const ShaderToyProject& project);

}  // namespace shaderport::driver::project
