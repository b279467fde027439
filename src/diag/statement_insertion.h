// Fix-its that add a statement to a block so that the result reads as if a person
// had written it: on a line of its own, indented as the block's statements, when the
// brace stands at the end (opening) or the start (closing) of its line; inline, one
// space apart, in a block written on one line.
#pragma once

#include <cstdint>
#include <string_view>

#include "diag/diagnostic.h"
#include "source/source_file.h"

namespace shaderport {

// Adds `statement` ("O = vec4(0.0);") as the first statement of the block whose
// opening brace ends at byte `brace_end` of `file`.
FixIt InsertFirstStatement(const SourceFile& file, uint32_t brace_end, std::string_view statement);

// Adds `statement` as the last statement of the block whose closing brace begins at
// byte `brace_begin` of `file`.
FixIt InsertLastStatement(const SourceFile& file, uint32_t brace_begin, std::string_view statement);

}  // namespace shaderport
