// What the fix and port targets share: glslang's verdict on a text, asked the
// way the library asks it (src/driver/port/port_file.cpp), and a failing check
// that libFuzzer records as a crash.
#pragma once

#include <cstddef>
#include <string_view>

#include "driver/dialect.h"
#include "fuzz_check.h"
#include "source/source_manager.h"

namespace shaderport::fuzz {

// Error diagnostics glslang reports for `text` read as `kind` (a ShaderToy pass
// is composed with the site's header; other code is compiled alone) when
// `as_output` is false, or as the WebGL2 text a port writes when it is true.
size_t ValidationErrors(std::string_view text, const driver::DetectedKind& kind, bool as_output,
                        SourceManager& sources);

// Every range of `diagnostics`-like data must lie inside a file of `sources`.
bool RangeInside(const SourceManager& sources, const SourceRange& range);

}  // namespace shaderport::fuzz
