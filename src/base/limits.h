// Explicit resource limits. Each breach is a diagnostic, never a crash; see docs/limits.md.
#pragma once

#include <cstddef>
#include <cstdint>

namespace shaderport::limits {

inline constexpr size_t kMaxFileBytes = 8u << 20;  // 8 MiB per input file
// A .jsonl file holds many projects, one a line: the limit of one file applies to each
// line (one project), and the whole file may hold this much.
inline constexpr size_t kMaxJsonLinesBytes = 512u << 20;  // 512 MiB per .jsonl file
inline constexpr size_t kMaxTokens = 2'000'000;           // lexed tokens per file
inline constexpr size_t kMaxExpandedTokens = 4'000'000;   // tokens after macro expansion
// Preprocessed tokens of one shader (Common code included) that glslang is given: its
// memory grows with them (about 1 GiB at 2,000,000), and every command runs under 2 GiB.
inline constexpr size_t kMaxCompiledTokens = 1'000'000;
// Syntax-tree depth given to glslang's SPIR-V generator, which recurses once per level (a
// chain of 400,000 terms overflowed its 256 MiB stack). Browsers stop at 256 levels.
inline constexpr uint32_t kMaxSpirvTreeDepth = 10'000;
inline constexpr uint32_t kMaxMacroDepth = 200;        // nested macro expansions
inline constexpr uint32_t kMaxConditionalDepth = 200;  // nested #if groups
// Browsers' GLSL parsers (ANGLE's, made by bison) keep at most 10,000 entries on their
// stack and reject deeper code with "memory exhausted": about 9,990 nested parentheses,
// 3,330 nested `?:` or 1,665 nested `if`s. Our parser estimates that stack per construct
// (glsl/syntax/browser_stack.h) and stops where they do; its own recursion stays below
// this many levels too.
inline constexpr uint32_t kBrowserParserStack = 10'000;
inline constexpr size_t kMaxDiagnosticsPerFile = 1000;  // further ones are dropped with a note
// Files read besides inputs (docs/limits.md, "Other files"): larger ones are refused
// before a byte is read.
inline constexpr size_t kMaxReportBytes = 64u << 20;      // a --baseline or a report to merge
inline constexpr size_t kMaxImageBytes = 64u << 20;       // a channel PNG
inline constexpr size_t kMaxCacheEntryBytes = 64u << 20;  // a result cache entry
inline constexpr size_t kMaxConfigBytes = 1u << 20;       // a .shaderport.toml or dialect TOML
// A render's text goes through spirv-opt only while its entry point, with every call
// inlined, stays below this many SPIR-V instructions (past it, tens of seconds).
inline constexpr uint64_t kMaxInlinedInstructions = 40'000;
// SPIRV-Cross (port --emit hlsl|msl|essl-roundtrip) walks a callee's body again at every
// call: the same count, with more room, as each visit is cheap (reflect: the limit above).
inline constexpr uint64_t kMaxCrossCompiledInstructions = 4'000'000;

}  // namespace shaderport::limits
