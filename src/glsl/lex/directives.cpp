#include <algorithm>
#include <cstdlib>
#include <limits>
#include <string>

#include "base/limits.h"
#include "glsl/lex/macro_definitions.h"
#include "glsl/lex/macro_expander.h"
#include "glsl/lex/pp_driver.h"
#include "glsl/lex/pp_expression.h"

namespace shaderport::glsl {
namespace {

bool IsConditional(std::string_view name) {
  return name == "if" || name == "ifdef" || name == "ifndef" || name == "elif" || name == "else" ||
         name == "endif";
}

}  // namespace

void PpDriver::Directive(std::span<const Token> line) {
  const SourceRange range{file_->Id(), line.front().begin, line.back().end};
  if (line.size() == 1) return;  // the null directive "#"
  const Token& name_token = line[1];
  const std::string_view name =
      name_token.kind == TokenKind::kIdentifier ? name_token.text : std::string_view();
  const std::span<const Token> args = line.subspan(2);
  if (IsConditional(name)) {
    Conditional(name, line, range);
    return;
  }
  if (!Active()) return;  // only conditionals matter in skipped groups
  for (const Token& t : args) CheckIdentifierLength(t);
  if (name == "define") {
    DefineMacro(state_, *file_, args, range);
  } else if (name == "undef") {
    UndefineMacro(state_, *file_, args, range);
  } else if (name == "version") {
    Version(args, range);
  } else if (name == "extension") {
    Extension(args, range);
  } else if (name == "line") {
    Line(args, range);
  } else if (name == "pragma") {
    std::string text;
    for (const Token& t : args) text += (text.empty() ? "" : " ") + std::string(t.text);
    state_.result.pragmas.push_back({std::move(text), range});
  } else if (name == "error") {
    const std::string_view text =
        args.empty()
            ? std::string_view()
            : file_->Text().substr(args.front().begin, args.back().end - args.front().begin);
    state_.Report(Severity::kError, "preprocessor/error-directive", range,
                  "#error " + std::string(text));
  } else {
    state_.Report(Severity::kError, "preprocessor/unknown-directive", RangeOf(name_token),
                  "unknown preprocessor directive '#" + std::string(name_token.text) + "'");
  }
}

void PpDriver::Conditional(std::string_view name, std::span<const Token> line, SourceRange range) {
  const bool was_active = Active();
  const std::span<const Token> args = line.subspan(2);
  if (name == "if" || name == "ifdef" || name == "ifndef") {
    ConditionalGroup g;
    g.directive = range;
    g.parent_active = was_active;
    if (groups_.size() >= limits::kMaxConditionalDepth) {
      if (!reported_depth_) {
        reported_depth_ = true;
        state_.Report(Severity::kError, "preprocessor/conditional-too-deep", range,
                      "#if groups nested more than " +
                          std::to_string(limits::kMaxConditionalDepth) +
                          " deep; the deeper ones are skipped");
      }
      g.parent_active = false;  // skip the whole group, but keep matching its #endif
    }
    g.taken = !g.parent_active || Condition(name, args, range);
    g.active = g.parent_active && g.taken;
    groups_.push_back(g);
  } else if (groups_.empty()) {
    state_.Report(Severity::kError, "preprocessor/unmatched-conditional", range,
                  "#" + std::string(name) + " without #if");
    return;
  } else if (name == "endif") {
    if (!args.empty()) {
      state_.Report(Severity::kWarning, "preprocessor/extra-tokens", RangeOf(args.front()),
                    "extra tokens after #endif are ignored");
    }
    groups_.pop_back();
  } else {
    ConditionalGroup& g = groups_.back();
    if (g.else_seen) {
      state_.Report(Severity::kError, "preprocessor/unmatched-conditional", range,
                    "#" + std::string(name) + " after #else");
    }
    if (name == "else") {
      if (!args.empty()) {
        state_.Report(Severity::kWarning, "preprocessor/extra-tokens", RangeOf(args.front()),
                      "extra tokens after #else are ignored");
      }
      g.else_seen = true;
      g.active = g.parent_active && !g.taken;
      g.taken = true;
    } else {  // elif: evaluated only when no earlier branch was chosen
      g.active = g.parent_active && !g.taken && !g.else_seen && Condition("if", args, range);
      g.taken = g.taken || g.active;
    }
  }
  const bool now_active = Active();
  if (was_active && !now_active) skip_begin_ = range.end;
  if (!was_active && now_active) {
    state_.result.inactive_regions.push_back({file_->Id(), skip_begin_, range.begin});
  }
}

bool PpDriver::Condition(std::string_view name, std::span<const Token> args, SourceRange range) {
  if (name == "if") {
    std::vector<ExpToken> expanded = ExpandMacros(state_, ToExpTokens(args), true);
    return EvaluateCondition(state_, expanded, range);
  }
  if (args.empty() || args[0].kind != TokenKind::kIdentifier) {
    state_.Report(Severity::kError, "preprocessor/invalid-directive",
                  args.empty() ? range : RangeOf(args[0]),
                  "#" + std::string(name) + " must be followed by a macro name");
    return false;
  }
  if (args.size() > 1) {
    state_.Report(Severity::kWarning, "preprocessor/extra-tokens", RangeOf(args[1]),
                  "extra tokens after the macro name are ignored");
  }
  const bool defined = state_.Find(args[0].text) != nullptr;
  return name == "ifdef" ? defined : !defined;
}

void PpDriver::Version(std::span<const Token> args, SourceRange range) {
  VersionDirective& v = state_.result.version;
  if (file_index_ != 0 || seen_token_ || v.present) {
    state_.Report(Severity::kError, "preprocessor/version-not-first", range,
                  "#version must come before everything else except comments and white space");
    if (v.present) return;
  }
  if (args.empty() || args[0].kind != TokenKind::kIntLiteral) {
    state_.Report(Severity::kError, "preprocessor/invalid-version", range,
                  "#version must be followed by a version number");
    return;
  }
  // Read as a C integer literal, as browsers do: `0300` is octal (192), `0x12C` is 300.
  const int number = static_cast<int>(
      std::clamp(std::strtol(std::string(args[0].text).c_str(), nullptr, 0), 0L, 100000L));
  const std::string profile = args.size() > 1 ? std::string(args[1].text) : std::string();
  if (args.size() > 2 || (args.size() > 1 && args[1].kind != TokenKind::kIdentifier)) {
    state_.Report(Severity::kError, "preprocessor/invalid-version", range,
                  "unexpected tokens after #version " + std::string(args[0].text));
  }
  v.present = true;
  v.number = number;
  v.profile = profile;
  v.range = range;
  const bool es100 = number == 100 && profile.empty();
  const bool es300 = number == 300 && profile == "es";
  if (es300 && file_->LocationOf(range.begin).line != 1) {
    // ANGLE, hence WebGL 2, wants ESSL 3.00's #version on the very first line.
    state_.Report(Severity::kError, "preprocessor/version-not-first", range,
                  "'#version 300 es' must be on the first line of the shader");
  }
  if (!es100 && !es300) {
    state_.Report(Severity::kError, "preprocessor/unsupported-version", range,
                  "WebGL accepts only '#version 100' (GLSL ES 1.00) and '#version 300 es' "
                  "(GLSL ES 3.00)");
  }
}

void PpDriver::Extension(std::span<const Token> args, SourceRange range) {
  const bool well_formed = args.size() == 3 && args[0].kind == TokenKind::kIdentifier &&
                           args[1].punct == Punct::kColon && args[2].kind == TokenKind::kIdentifier;
  const std::string_view behavior = well_formed ? args[2].text : std::string_view();
  if (!well_formed || (behavior != "require" && behavior != "enable" && behavior != "warn" &&
                       behavior != "disable")) {
    state_.Report(Severity::kError, "preprocessor/invalid-extension", range,
                  "expected '#extension name : require|enable|warn|disable'");
    return;
  }
  if (args[0].text == "all" && (behavior == "require" || behavior == "enable")) {
    state_.Report(Severity::kError, "preprocessor/invalid-extension", range,
                  "'#extension all' accepts only 'warn' or 'disable'");
    return;
  }
  if (seen_code_) {
    // ESSL 3.00 section 3.5 requires extensions before any code; ES 1.00 drivers accept it.
    const bool es3 = state_.result.version.number >= 300;
    state_.Report(es3 ? Severity::kError : Severity::kWarning, "preprocessor/extension-after-code",
                  range, "#extension should come before any code");
  }
  state_.result.extensions.push_back({std::string(args[0].text), std::string(behavior), range});
}

void PpDriver::Line(std::span<const Token> args, SourceRange range) {
  std::vector<ExpToken> expanded = ExpandMacros(state_, ToExpTokens(args), false);
  const auto is_int = [&](size_t i) {
    return i < expanded.size() && expanded[i].token.kind == TokenKind::kIntLiteral;
  };
  if (expanded.empty() || expanded.size() > 2 || !is_int(0) ||
      (expanded.size() == 2 && !is_int(1))) {
    state_.Report(Severity::kError, "preprocessor/invalid-line", range,
                  "expected '#line line' or '#line line source-string-number'");
    return;
  }
  const long line = std::strtol(std::string(expanded[0].token.text).c_str(), nullptr, 0);
  if (line > std::numeric_limits<int32_t>::max()) {  // browsers: "integer overflow"
    state_.Report(Severity::kError, "preprocessor/line-too-large", range,
                  "#line " + std::string(expanded[0].token.text) + " does not fit in a 32-bit int");
    return;
  }
  const auto physical_next = static_cast<long>(file_->LocationOf(range.end).line) + 1;
  state_.line_delta = static_cast<int64_t>(line) - physical_next;
  if (expanded.size() == 2) {
    state_.source_number = static_cast<int>(std::clamp(
        std::strtol(std::string(expanded[1].token.text).c_str(), nullptr, 0), 0L, 1L << 30));
  }
}

}  // namespace shaderport::glsl
