// The one way every command reports an error (docs/cli.md, "Exit codes and
// errors"): `shaderport: error: MESSAGE` on standard error, one line each.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace shaderport::cli {

// Prints `shaderport: error: MESSAGE`.
void PrintError(std::string_view message);

// Prints `shaderport: note: PATH: not written: ...` for each ported input whose
// output does not compile (port writes it only with --write-invalid).
void PrintUnwritten(std::span<const std::filesystem::path> unwritten);

// Prints the error and returns the exit code of a usage or input error (2).
int UsageError(std::string_view message);

// "unknown --format 'jsn'; did you mean 'json'?" when one name is near, else
// "unknown --format 'x' (expected text, json, sarif or github)".
std::string UnknownName(std::string_view what, std::string_view typed,
                        std::span<const std::string> names);

// "; did you mean 'NAME'?" for the nearest of `names`, or "" when none is near.
std::string DidYouMean(std::string_view typed, std::span<const std::string> names);

}  // namespace shaderport::cli
