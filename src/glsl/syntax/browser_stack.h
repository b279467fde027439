// Entries a construct keeps on a browser's parser stack while the code inside it is
// parsed. ANGLE's parser is an LALR parser made by bison: `(` stays on its stack until
// the matching `)`, `a +` until the right operand is reduced, and so on; past
// limits::kBrowserParserStack entries it stops with "memory exhausted". The numbers are
// read off ANGLE's grammar and fitted to Chromium 156 (docs/limits.md, "Nesting"):
// 9,988 nested parentheses in a local initialiser, 4,994 `-(`, 3,329 `2.0 * (`, 1,664
// `true ? 1.0 :` and 1,665 `if (true)` compile, one more does not. The estimate can be
// a level off at the boundary (what sits on top of the innermost construct differs).
#pragma once

#include <cstdint>

namespace shaderport::glsl::browser_stack {

// The parser's start state, the translation unit and what is on top of the deepest
// construct (its reduced expression and closing token).
inline constexpr uint32_t kBase = 5;
inline constexpr uint32_t kParenthesis = 1;       // (
inline constexpr uint32_t kPrefixOperator = 1;    // - ! ~ ++ --
inline constexpr uint32_t kRightOperand = 2;      // left operand, operator
inline constexpr uint32_t kAssignedValue = 2;     // target, assignment operator
inline constexpr uint32_t kConditionalTrue = 3;   // condition ? (and its action)
inline constexpr uint32_t kConditionalFalse = 6;  // condition ? expression : (two actions)
inline constexpr uint32_t kFirstArgument = 1;     // callee(
inline constexpr uint32_t kLaterArgument = 2;     // callee(arguments,
inline constexpr uint32_t kIndex = 2;             // base[
inline constexpr uint32_t kInitializer = 3;       // type name =
inline constexpr uint32_t kArraySize = 3;         // type name [
inline constexpr uint32_t kFunctionBody = 4;      // prototype, action, {, statements
inline constexpr uint32_t kBlock = 3;             // {, action, statements
inline constexpr uint32_t kCondition = 2;         // if ( / while ( / switch (
inline constexpr uint32_t kThenBranch = 6;        // if ( condition ) action
inline constexpr uint32_t kElseBranch = 9;        // if ( condition ) statement else action
inline constexpr uint32_t kLoopHeader = 3;        // for ( action
inline constexpr uint32_t kLoopBody = 7;          // for ( init rest ) / while ( cond ) action
inline constexpr uint32_t kDoBody = 3;            // do action
inline constexpr uint32_t kSwitchBody = 6;        // switch ( selector ) action
inline constexpr uint32_t kReturnValue = 1;       // return
inline constexpr uint32_t kStructBody = 5;        // struct name { action members

}  // namespace shaderport::glsl::browser_stack
