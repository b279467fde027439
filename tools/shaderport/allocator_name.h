// Which malloc the executable runs on, for `version` (see SHADERPORT_MIMALLOC in
// CMakeLists.txt).
#pragma once

#include <string>

namespace shaderport::cli {

std::string AllocatorName();

}  // namespace shaderport::cli
