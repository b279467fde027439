#include "report/github_format.h"

#include <algorithm>

#include "report/source_position.h"

namespace shaderport {
namespace {

const char* CommandFor(Severity severity) {
  switch (severity) {
    case Severity::kError:
      return "error";
    case Severity::kWarning:
      return "warning";
    case Severity::kNote:
      return "notice";
  }
  return "error";
}

std::string Escape(std::string_view text, bool property) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '%':
        out += "%25";
        break;
      case '\r':
        out += "%0D";
        break;
      case '\n':
        out += "%0A";
        break;
      case ':':
        out += property ? "%3A" : ":";
        break;
      case ',':
        out += property ? "%2C" : ",";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

std::string EscapeGithubData(std::string_view text) { return Escape(text, false); }
std::string EscapeGithubProperty(std::string_view text) { return Escape(text, true); }

std::string FormatGithub(const CheckReport& report, const ReportOptions& options) {
  std::string out;
  for (const FileReport& file : report.files) {
    for (const Diagnostic& diagnostic : file.diagnostics) {
      std::string properties;
      auto where = Resolve(report.sources, diagnostic.range);
      // A pass of a JSON project: the annotation goes on its bytes in the JSON file.
      if (where) {
        if (auto outer = ResolveInContainer(*where)) where = outer;
      }
      const SourceFile* shown = where && !where->file->IsSynthetic() ? where->file : file.file;
      if (shown != nullptr && shown->Embedded() != nullptr && shown->Embedded()->container)
        shown = shown->Embedded()->container.get();
      if (shown) {
        properties +=
            "file=" + EscapeGithubProperty(DisplayPath(shown->Name(), options.base_directory));
      }
      if (where && shown == where->file) {
        const LineColumn& start = where->start_utf16;
        const LineColumn& end = where->end_utf16;
        properties += ",line=" + std::to_string(start.line);
        // GitHub takes columns only for a range on one line; its end column is inclusive.
        if (start.line == end.line) {
          properties += ",col=" + std::to_string(start.column);
          properties += ",endLine=" + std::to_string(end.line);
          properties += ",endColumn=" + std::to_string(std::max(start.column, end.column - 1));
        } else {
          properties += ",endLine=" + std::to_string(end.line);
        }
      }
      if (!diagnostic.rule_id.empty()) {
        if (!properties.empty()) properties += ',';
        properties += "title=" + EscapeGithubProperty(diagnostic.rule_id);
      }
      // Annotations hold one message: notes follow it on their own lines.
      std::string message = diagnostic.message;
      for (const DiagnosticNote& note : diagnostic.notes) {
        message += "\nnote: ";
        if (const auto note_where = Resolve(report.sources, note.range)) {
          message += DisplayPath(note_where->file->Name(), options.base_directory) + ":" +
                     std::to_string(note_where->start.line) + ":" +
                     std::to_string(note_where->start.column) + ": ";
        }
        message += note.message;
      }
      out += "::" + std::string(CommandFor(diagnostic.severity));
      if (!properties.empty()) out += " " + properties;
      out += "::" + EscapeGithubData(message) + "\n";
    }
  }
  return out;
}

}  // namespace shaderport
