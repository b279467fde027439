#include "report/text_format.h"

#include <algorithm>
#include <optional>
#include <string_view>

#include "base/printable.h"
#include "report/source_position.h"

namespace shaderport {
namespace {

constexpr std::string_view kBold = "\x1b[1m";
constexpr std::string_view kRed = "\x1b[1;31m";
constexpr std::string_view kMagenta = "\x1b[1;35m";
constexpr std::string_view kCyan = "\x1b[1;36m";
constexpr std::string_view kGreen = "\x1b[1;32m";
constexpr std::string_view kReset = "\x1b[0m";

// Quoted text in fix-it lines is cut to this many bytes: the JSON output has it all.
constexpr size_t kMaxQuotedBytes = 60;
// A source line longer than kMaxSnippetBytes is shown as kSnippetWindowBytes around
// the finding, starting kSnippetContextBytes before it.
constexpr size_t kMaxSnippetBytes = 1024;
constexpr size_t kSnippetWindowBytes = 240;
constexpr size_t kSnippetContextBytes = 80;

bool IsContinuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

std::string Plural(size_t count, std::string_view word) {
  std::string out = std::to_string(count) + " " + std::string(word);
  if (count != 1) out += 's';
  return out;
}

// Shows text inside '...' on one line: newlines and tabs escaped, long text cut.
std::string Quote(std::string_view text) {
  std::string out = "'";
  size_t shown = 0;
  for (char c : text) {
    // Cut only before the first byte of a character, never inside a UTF-8 sequence.
    if (shown >= kMaxQuotedBytes && (static_cast<unsigned char>(c) & 0xC0) != 0x80) {
      out += "...";
      break;
    }
    ++shown;
    out += c;
  }
  // Control characters escaped after the cut, so that an escape is never cut in two.
  return "'" + EscapeControlCharacters(std::string_view(out).substr(1)) + "'";
}

class TextPrinter {
 public:
  TextPrinter(const CheckReport& report, const ReportOptions& options)
      : report_(report), options_(options) {}

  std::string Print() {
    for (const FileReport& file : report_.files) {
      for (const Diagnostic& diagnostic : file.diagnostics) PrintDiagnostic(file, diagnostic);
    }
    if (options_.summary_line) {
      const ReportSummary summary = Summarize(report_);
      out_ += Paint(kBold, SummaryLine(summary));
      out_ += '\n';
      if (summary.fixable > 0) out_ += FixableLine(summary) + '\n';
    }
    return std::move(out_);
  }

 private:
  std::string Paint(std::string_view colour, std::string_view text) const {
    if (!options_.color) return std::string(text);
    return std::string(colour) + std::string(text) + std::string(kReset);
  }

  std::string PathOf(const SourceFile* file) const {
    // A file or pass name may hold a newline or an escape sequence: it must not forge
    // a finding line or reach the terminal.
    return file ? EscapeControlCharacters(DisplayPath(file->Name(), options_.base_directory))
                : "<unknown>";
  }

  static std::string_view SeverityColour(Severity severity) {
    switch (severity) {
      case Severity::kError:
        return kRed;
      case Severity::kWarning:
        return kMagenta;
      case Severity::kNote:
        return kCyan;
    }
    return kRed;
  }

  // "path:line:col: severity: message" (or "path: ..." without a range).
  void PrintHeader(const std::optional<ResolvedRange>& where, const SourceFile* fallback,
                   Severity severity, std::string_view message, std::string_view rule_id,
                   bool fixable = false) {
    std::string location;
    if (where) {
      location = PathOf(where->file) + ":" + std::to_string(where->start.line) + ":" +
                 std::to_string(where->start.column) + ":";
    } else if (fallback) {
      location = PathOf(fallback) + ":";
    }
    if (!location.empty()) out_ += Paint(kBold, location) + " ";
    out_ += Paint(SeverityColour(severity), std::string(SeverityName(severity)) + ":");
    // One diagnostic is one line for tools that parse clang's format.
    // "[*]" marks what `shaderport fix` repairs, where ruff marks it.
    std::string text = std::string(fixable ? " [*] " : " ") + OneLinePrintable(message);
    if (!rule_id.empty()) text += " [" + EscapeControlCharacters(rule_id) + "]";
    out_ += Paint(kBold, text);
    out_ += '\n';
  }

  static std::string Gutter(uint32_t line) {
    std::string number = std::to_string(line);
    return std::string(number.size() < 5 ? 5 - number.size() : 0, ' ') + number + " | ";
  }

  // Spaces (tabs kept) that reach byte column `column` of `line`.
  static std::string PadTo(std::string_view line, uint32_t column) {
    std::string pad;
    const size_t limit = std::min<size_t>(column - 1, line.size());
    for (size_t i = 0; i < limit; ++i) {
      const auto byte = static_cast<unsigned char>(line[i]);
      if (byte == '\t') {
        pad += '\t';
      } else if ((byte & 0xC0) != 0x80) {
        pad += ' ';
      }
    }
    return pad;
  }

  // Control bytes could move the cursor or recolour a terminal: show them as spaces.
  static std::string Printable(std::string_view line) {
    std::string out(line);
    for (char& c : out) {
      const auto byte = static_cast<unsigned char>(c);
      if ((byte < 0x20 && byte != '\t') || byte == 0x7F) c = ' ';
    }
    return out;
  }

  // The source line, the caret line and, for an insertion on that line, the text
  // to insert under it. Returns the fix-it that was shown as an insertion line.
  // A line longer than kMaxSnippetBytes (minified or generated code, a one-line JSON
  // document) is shown as a window around the start of the range, marked "...":
  // printing it whole for each of its findings made output grow as findings x length.
  const FixIt* PrintSnippet(const ResolvedRange& where, const std::vector<FixIt>& fixes) {
    const std::string_view full_line = where.file->LineText(where.start.line);
    const std::string blank_gutter(Gutter(where.start.line).size() - 2, ' ');
    const uint32_t full_end_column = static_cast<uint32_t>(full_line.size()) + 1;
    const uint32_t start_index = std::min(where.start.column - 1, full_end_column - 1);
    size_t window_begin = 0;
    std::string_view line = full_line;
    if (full_line.size() > kMaxSnippetBytes) {
      window_begin = start_index > kSnippetContextBytes ? start_index - kSnippetContextBytes : 0;
      while (window_begin > 0 && IsContinuationByte(full_line[window_begin])) --window_begin;
      size_t window_end = std::min(full_line.size(), window_begin + kSnippetWindowBytes);
      while (window_end < full_line.size() && IsContinuationByte(full_line[window_end])) {
        --window_end;
      }
      line = full_line.substr(window_begin, window_end - window_begin);
    }
    const std::string before = window_begin > 0 ? "..." : "";
    const std::string after = window_begin + line.size() < full_line.size() ? "..." : "";
    out_ += Gutter(where.start.line) + before + Printable(line) + after + '\n';

    // Columns inside the window; a range over several lines, or past the window, is
    // underlined to the end of what is shown.
    const auto shift = static_cast<uint32_t>(window_begin);
    const uint32_t line_end_column = static_cast<uint32_t>(line.size()) + 1;
    const uint32_t end_column =
        where.end.line == where.start.line ? where.end.column - shift : line_end_column;
    const uint32_t start = start_index - shift;
    const uint32_t end_index = std::max(std::min(end_column - 1, line_end_column - 1), start);
    const uint32_t width = CountCodePoints(line.substr(start, end_index - start));
    std::string marks = "^";
    if (width > 1) marks += std::string(width - 1, '~');
    const std::string pad(before.size(), ' ');
    out_ += blank_gutter + "| " + pad + PadTo(line, start + 1) + Paint(kGreen, marks) + '\n';
    if (full_line.size() > kMaxSnippetBytes) return nullptr;  // fixes get their own lines

    for (const FixIt& fix : fixes) {
      auto fix_where = Resolve(report_.sources, fix.range);
      if (!fix_where || fix_where->file != where.file ||
          fix_where->start.line != where.start.line ||
          fix_where->begin_offset != fix_where->end_offset ||
          fix.replacement.find_first_of("\r\n") != std::string::npos) {
        continue;
      }
      out_ += blank_gutter + "| " + PadTo(line, fix_where->start.column) +
              Paint(kGreen, Printable(fix.replacement)) + '\n';
      return &fix;
    }
    return nullptr;
  }

  void PrintFixIt(const FixIt& fix, const std::optional<ResolvedRange>& primary) {
    auto where = Resolve(report_.sources, fix.range);
    if (!where) return;
    const std::string_view old_text =
        where->file->Text().substr(where->begin_offset, where->end_offset - where->begin_offset);
    std::string line = "  fix-it: ";
    if (old_text.empty()) {
      line += "insert " + Quote(fix.replacement);
    } else if (fix.replacement.empty()) {
      line += "remove " + Quote(old_text);
    } else {
      line += "replace " + Quote(old_text) + " with " + Quote(fix.replacement);
    }
    // Say where when the fix is not on the line shown above it.
    if (!primary || primary->file != where->file || primary->start.line != where->start.line ||
        old_text.empty()) {
      line += " at ";
      if (!primary || primary->file != where->file) line += PathOf(where->file) + ":";
      line += std::to_string(where->start.line) + ":" + std::to_string(where->start.column);
    }
    if (fix.safety == FixSafety::kSuggestion) line += " (suggestion)";
    out_ += line + '\n';
  }

  void PrintDiagnostic(const FileReport& file, const Diagnostic& diagnostic) {
    const auto where = Resolve(report_.sources, diagnostic.range);
    PrintHeader(where, file.file, diagnostic.severity, diagnostic.message, diagnostic.rule_id,
                IsFixable(diagnostic));
    const FixIt* shown = where ? PrintSnippet(*where, diagnostic.fixes) : nullptr;
    for (const FixIt& fix : diagnostic.fixes) {
      if (&fix != shown) PrintFixIt(fix, where);
    }
    for (const DiagnosticNote& note : diagnostic.notes) {
      const auto note_where = Resolve(report_.sources, note.range);
      PrintHeader(note_where, nullptr, Severity::kNote, note.message, "");
      if (note_where) PrintSnippet(*note_where, {});
    }
  }

  const CheckReport& report_;
  const ReportOptions& options_;
  std::string out_;
};

}  // namespace

std::string SummaryLine(const ReportSummary& summary) {
  std::string line = Plural(summary.errors, "error") + ", " + Plural(summary.warnings, "warning");
  if (summary.notes > 0) line += ", " + Plural(summary.notes, "note");
  line += " in " + Plural(summary.files_with_problems, "file") + " (";
  // Tabs of ShaderToy projects are counted as such, beside the shader files.
  const size_t files = summary.files_checked - summary.tabs_checked;
  if (summary.tabs_checked == 0) return line + Plural(files, "file") + " checked)";
  if (files > 0) line += Plural(files, "file") + " and ";
  return line + Plural(summary.tabs_checked, "tab") + " of " +
         Plural(summary.projects, "ShaderToy project") + " checked)";
}

std::string FixableLine(const ReportSummary& summary) {
  return "[*] " + std::to_string(summary.fixable) + " fixable with 'shaderport fix'";
}

std::string FormatText(const CheckReport& report, const ReportOptions& options) {
  return TextPrinter(report, options).Print();
}

}  // namespace shaderport
