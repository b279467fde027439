// Which findings are breaches of shaderport's own resource limits (docs/limits.md).
// Text that breached one is not handed to glslang, SPIRV-Tools or SPIRV-Cross and is
// not rewritten by fixes: every command stops there, as `check` does.
#pragma once

#include <string_view>

#include "diag/diagnostic.h"

namespace shaderport {

bool IsLimitBreach(std::string_view rule_id);

// True when one of `diagnostics` is a limit breach.
bool HasLimitBreach(const DiagnosticList& diagnostics);

// The limit breaches of `diagnostics`, in order.
DiagnosticList LimitBreaches(const DiagnosticList& diagnostics);

}  // namespace shaderport
