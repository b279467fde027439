// Small helpers shared by the webgl2/* rules: fresh names, whole-line ranges,
// fix-it construction and the top-of-file insertion point.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"
#include "glsl/syntax/ast.h"
#include "rule/rule_context.h"

namespace shaderport::rules::webgl2 {

// True when `range` lies in the file being ported (not Common, not a header).
bool InThisFile(const rule::RuleContext& context, const SourceRange& range);

// True when `name` is spelled anywhere in the shader (file, Common, macros), is a
// keyword or reserved word of GLSL ES 3.00, starts with "gl_" or names a built-in.
bool NameTaken(const rule::RuleContext& context, std::string_view name);

// `first` when it is free, else `first` + "_1", "_2", ... (never with "__", which
// GLSL reserves).
std::string FreshName(const rule::RuleContext& context, std::string_view first);

// From the start of the line holding `range.begin` to the start of the line after
// `range.end` (or the end of the text): deleting it removes the lines entirely.
SourceRange WholeLines(const SourceFile& file, const SourceRange& range);

// Offset just after the leading `#version` and `#extension` lines (and blank or
// comment lines between them) of the file: where a declaration that must come
// before any code is inserted. `saw_version` tells whether a #version was seen.
uint32_t AfterLeadingDirectives(const rule::RuleContext& context, bool* saw_version);

// The range a fix should edit to rename `name` written by `node`: `name_range`
// itself in plain code; the token's spelling inside a #define body when the name
// comes from one (RuleContext::Report then applies it only when every expansion
// agrees); `name_range` otherwise (Report drops fixes at macro use sites).
SourceRange NameFixRange(const rule::RuleContext& context, const glsl::Node& node,
                         const SourceRange& name_range, std::string_view name);

// Reports `diagnostic`; fix-its that edit a #define body are split off into
// diagnostics of their own (same rule and message) because
// RuleContext applies a body edit only when every expansion proposes it alone.
void ReportSplittingMacroBodies(rule::RuleContext& context, Diagnostic diagnostic);

// One `#extension` line as written, found in the lexed text (so also inside #if
// groups that are inactive here but may be active in a browser).
struct ExtensionLine {
  std::string name;
  SourceRange range;  // from '#' to the last token of the line
};
std::vector<ExtensionLine> ExtensionLines(const rule::RuleContext& context);

FixIt Replace(const SourceRange& range, std::string text);
FixIt Insert(FileId file, uint32_t offset, std::string text);

Diagnostic MakeDiagnostic(std::string_view rule_id, Severity severity, const SourceRange& range,
                          std::string message);

}  // namespace shaderport::rules::webgl2
