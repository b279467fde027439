#include "rules/port/port_support.h"

#include "glsl/sema/builtins.h"
#include "glsl/syntax/keywords.h"
#include "rule/macro_fixes.h"

namespace shaderport::rules::webgl2 {

bool InThisFile(const rule::RuleContext& context, const SourceRange& range) {
  return range.Valid() && range.file == context.File().Id() && range.end <= context.Text().size();
}

bool NameTaken(const rule::RuleContext& context, std::string_view name) {
  if (name.starts_with("gl_")) return true;
  if (glsl::ClassifyWord(name, 300).status != glsl::WordStatus::kIdentifier) return true;
  if (glsl::ClassifyWord(name, 100).status != glsl::WordStatus::kIdentifier) return true;
  if (glsl::IsBuiltinFunctionName(name)) return true;
  for (const auto& token : context.Lexed().tokens) {
    if (token.kind == glsl::TokenKind::kIdentifier && token.text == name) return true;
  }
  for (const auto& token : context.Preprocessed().tokens) {
    if (token.kind == glsl::TokenKind::kIdentifier && token.text == name) return true;
  }
  return false;
}

std::string FreshName(const rule::RuleContext& context, std::string_view first) {
  if (!NameTaken(context, first)) return std::string(first);
  const bool ends_with_underscore = !first.empty() && first.back() == '_';
  // The shader has finitely many identifiers, so this ends; the bound is a guard.
  for (int n = 1; n < 1'000'000; ++n) {
    std::string candidate =
        std::string(first) + (ends_with_underscore ? "" : "_") + std::to_string(n);
    if (!NameTaken(context, candidate)) return candidate;
  }
  return std::string(first) + "_shaderport";
}

SourceRange WholeLines(const SourceFile& file, const SourceRange& range) {
  const uint32_t first_line = file.LocationOf(range.begin).line;
  const uint32_t last_line = file.LocationOf(range.end).line;
  const uint32_t begin = file.LineStart(first_line);
  uint32_t end = static_cast<uint32_t>(file.Text().size());
  if (last_line < file.LineCount()) end = file.LineStart(last_line + 1);
  return {file.Id(), begin, end};
}

uint32_t AfterLeadingDirectives(const rule::RuleContext& context, bool* saw_version) {
  const auto& tokens = context.Lexed().tokens;
  const SourceFile& file = context.File();
  uint32_t offset = 0;
  bool version = false;
  for (size_t i = 0; i + 1 < tokens.size(); ++i) {
    const auto& hash = tokens[i];
    if (hash.kind != glsl::TokenKind::kHash) break;
    const auto& word = tokens[i + 1];
    const bool is_version = word.text == "version";
    if (word.at_line_start || (!is_version && word.text != "extension")) break;
    version = version || is_version;
    // Skip to the last token of the directive's line.
    size_t last = i + 1;
    while (last + 1 < tokens.size() && !tokens[last + 1].at_line_start &&
           tokens[last + 1].kind != glsl::TokenKind::kEndOfFile) {
      ++last;
    }
    offset = WholeLines(file, {file.Id(), hash.begin, tokens[last].end}).end;
    i = last;
  }
  if (saw_version != nullptr) *saw_version = version;
  return offset;
}

SourceRange NameFixRange(const rule::RuleContext& context, const glsl::Node& node,
                         const SourceRange& name_range, std::string_view name) {
  if (!context.InMacro(name_range) || !node.HasTokens()) return name_range;
  const auto& tokens = context.Preprocessed().tokens;
  for (uint32_t i = node.first_token; i <= node.last_token && i < tokens.size(); ++i) {
    const glsl::PpToken& token = tokens[i];
    if (token.text == name && token.in_macro_body && token.spelling.file == context.File().Id() &&
        token.expansion.Contains(name_range)) {
      return token.spelling;
    }
  }
  return name_range;
}

void ReportSplittingMacroBodies(rule::RuleContext& context, Diagnostic diagnostic) {
  std::vector<FixIt> plain;
  std::vector<FixIt> in_body;
  for (FixIt& fix : diagnostic.fixes) {
    const bool body =
        rule::PlacementOf(context.Preprocessed(), fix.range) == rule::MacroPlacement::kBody;
    (body ? in_body : plain).push_back(std::move(fix));
  }
  if (in_body.empty() || plain.empty()) {
    diagnostic.fixes = in_body.empty() ? std::move(plain) : std::move(in_body);
    context.Report(std::move(diagnostic));
    return;
  }
  diagnostic.fixes = std::move(plain);
  for (FixIt& fix : in_body) {
    Diagnostic part = MakeDiagnostic(diagnostic.rule_id, diagnostic.severity, diagnostic.range,
                                     diagnostic.message + " (in a macro body)");
    part.fixes.push_back(std::move(fix));
    context.Report(std::move(part));
  }
  context.Report(std::move(diagnostic));
}

std::vector<ExtensionLine> ExtensionLines(const rule::RuleContext& context) {
  std::vector<ExtensionLine> lines;
  const auto& tokens = context.Lexed().tokens;
  for (size_t i = 0; i + 2 < tokens.size(); ++i) {
    if (tokens[i].kind != glsl::TokenKind::kHash || tokens[i + 1].at_line_start ||
        tokens[i + 1].text != "extension") {
      continue;
    }
    size_t last = i + 1;
    while (last + 1 < tokens.size() && !tokens[last + 1].at_line_start &&
           tokens[last + 1].kind != glsl::TokenKind::kEndOfFile) {
      ++last;
    }
    if (last >= i + 2 && tokens[i + 2].kind == glsl::TokenKind::kIdentifier) {
      lines.push_back({std::string(tokens[i + 2].text),
                       {context.File().Id(), tokens[i].begin, tokens[last].end}});
    }
    i = last;
  }
  return lines;
}

FixIt Replace(const SourceRange& range, std::string text) {
  return FixIt{range, std::move(text), FixSafety::kSafe};
}

FixIt Insert(FileId file, uint32_t offset, std::string text) {
  return FixIt{{file, offset, offset}, std::move(text), FixSafety::kSafe};
}

Diagnostic MakeDiagnostic(std::string_view rule_id, Severity severity, const SourceRange& range,
                          std::string message) {
  return shaderport::MakeDiagnostic(severity, std::string(rule_id), range, std::move(message));
}

}  // namespace shaderport::rules::webgl2
