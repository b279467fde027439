#include <toml++/toml.h>

#include <algorithm>
#include <string>

#include "driver/config/config.h"
#include "driver/config/glob.h"
#include "driver/config/rule_pattern.h"

namespace shaderport::driver {
namespace {

// "; did you mean 'glslang/missing-precision'?" for a likely typo, else "".
std::string Suggestion(std::string_view pattern) {
  const std::optional<std::string> near = NearestCatalogPattern(pattern);
  return near ? "; did you mean '" + *near + "'?" : "";
}

class ConfigParser {
 public:
  explicit ConfigParser(const SourceFile& file) : file_(file) {
    result_.config.directory = std::filesystem::path(file.Name()).parent_path();
  }

  ConfigResult Run() {
    toml::table root;
    try {
      root = toml::parse(file_.Text(), std::string_view(file_.Name()));
    } catch (const toml::parse_error& error) {
      Report(Severity::kError, "config/syntax-error", error.source(),
             "invalid TOML: " + std::string(error.description()));
      return std::move(result_);
    }
    for (auto&& [key, value] : root) {
      if (key == "rules") {
        ReadRules(key, value);
      } else if (key == "check") {
        ReadCheck(key, value);
      } else if (key == "files") {
        ReadFiles(key, value);
      } else {
        UnknownKey(key, "a top-level table; expected [rules], [check] or [[files]]");
      }
    }
    // toml++ tables iterate in key order: report in file order instead.
    std::stable_sort(
        result_.diagnostics.begin(), result_.diagnostics.end(),
        [](const Diagnostic& a, const Diagnostic& b) { return a.range.begin < b.range.begin; });
    return std::move(result_);
  }

 private:
  // toml++ counts columns in characters; SourceFile offsets are bytes.
  uint32_t OffsetOf(const toml::source_position& position) const {
    const uint32_t line_start = file_.LineStart(position.line);
    const std::string_view line = file_.LineText(position.line);
    uint32_t characters = 1;
    size_t i = 0;
    for (; i < line.size() && characters < position.column; ++i) {
      if ((static_cast<unsigned char>(line[i]) & 0xC0) != 0x80) ++characters;
      // Step over the rest of a multi-byte character.
      while (i + 1 < line.size() && (static_cast<unsigned char>(line[i + 1]) & 0xC0) == 0x80) ++i;
    }
    return line_start + static_cast<uint32_t>(i);
  }

  SourceRange RangeOf(const toml::source_region& region) const {
    if (!region.begin) return {file_.Id(), 0, 0};
    const uint32_t begin = OffsetOf(region.begin);
    const uint32_t end = region.end ? std::max(begin, OffsetOf(region.end)) : begin;
    return {file_.Id(), begin, end};
  }

  void Report(Severity severity, std::string rule, const toml::source_region& where,
              std::string message) {
    result_.diagnostics.push_back(
        MakeDiagnostic(severity, std::move(rule), RangeOf(where), std::move(message)));
  }

  void UnknownKey(const toml::key& key, std::string_view what) {
    Report(
        Severity::kWarning, "config/unknown-key", key.source(),
        "unknown key '" + std::string(key.str()) + "' in " + std::string(what) + "; it is ignored");
  }

  void BadValue(const toml::node& node, std::string message) {
    Report(Severity::kError, "config/invalid-value", node.source(), std::move(message));
  }

  const toml::table* ExpectTable(const toml::key& key, const toml::node& node) {
    if (const toml::table* table = node.as_table()) return table;
    BadValue(node, "'" + std::string(key.str()) + "' must be a table");
    return nullptr;
  }

  std::optional<std::string> ExpectString(const toml::key& key, const toml::node& node) {
    if (const auto* value = node.as_string()) return value->get();
    BadValue(node, "'" + std::string(key.str()) + "' must be a string");
    return std::nullopt;
  }

  void ReadRules(const toml::key& key, const toml::node& node) {
    const toml::table* table = ExpectTable(key, node);
    if (!table) return;
    for (auto&& [pattern_key, value] : *table) {
      const std::string pattern(pattern_key.str());
      if (!IsValidRulePattern(pattern)) {
        Report(Severity::kError, "config/invalid-value", pattern_key.source(),
               "'" + pattern + "' is not a rule id; write 'category/name' or 'category/*'");
        continue;
      }
      const std::optional<std::string> name = ExpectString(pattern_key, value);
      if (!name) continue;
      const std::optional<RuleLevel> level = ParseRuleLevel(*name);
      if (!level) {
        BadValue(value, "'" + *name + "' is not a rule level; use off, note, warning or error");
        continue;
      }
      if (!RulePatternMatchesCatalog(pattern)) {
        Report(Severity::kWarning, "config/unknown-rule", pattern_key.source(),
               "'" + pattern + "' matches no rule shaderport knows" + Suggestion(pattern));
      }
      result_.config.rules.push_back({pattern, *level});
    }
  }

  void ReadGlobs(const toml::key& key, const toml::node& node, std::vector<std::string>& out) {
    const toml::array* array = node.as_array();
    if (!array) {
      BadValue(node, "'" + std::string(key.str()) + "' must be an array of glob strings");
      return;
    }
    for (const toml::node& item : *array) {
      const auto* glob = item.as_string();
      if (!glob) {
        BadValue(item, "'" + std::string(key.str()) + "' must hold only strings");
        continue;
      }
      if (std::string error = GlobError(glob->get()); !error.empty()) {
        BadValue(item, "invalid glob '" + glob->get() + "': " + error);
        continue;
      }
      out.push_back(glob->get());
    }
  }

  void ReadCheck(const toml::key& key, const toml::node& node) {
    const toml::table* table = ExpectTable(key, node);
    if (!table) return;
    for (auto&& [name, value] : *table) {
      if (name == "fail-on") {
        const std::optional<std::string> text = ExpectString(name, value);
        if (!text) continue;
        const std::optional<RuleLevel> level = ParseRuleLevel(*text);
        if (!level || *level == RuleLevel::kOff) {
          BadValue(value, "fail-on must be error, warning or note, not '" + *text + "'");
          continue;
        }
        result_.config.fail_on = *level == RuleLevel::kNote      ? Severity::kNote
                                 : *level == RuleLevel::kWarning ? Severity::kWarning
                                                                 : Severity::kError;
      } else if (name == "include") {
        ReadGlobs(name, value, result_.config.include);
      } else if (name == "exclude") {
        ReadGlobs(name, value, result_.config.exclude);
      } else {
        UnknownKey(name, "[check]; expected fail-on, include or exclude");
      }
    }
  }

  void ReadFiles(const toml::key& key, const toml::node& node) {
    const toml::array* array = node.as_array();
    if (!array || !array->is_array_of_tables()) {
      BadValue(node, "'files' must be an array of tables ([[files]])");
      return;
    }
    for (const toml::node& item : *array) ReadFileEntry(key, *item.as_table());
  }

  void ReadFileEntry(const toml::key& files_key, const toml::table& table) {
    FileOverride entry;
    bool ok = true;
    for (auto&& [name, value] : table) {
      const std::optional<std::string> text =
          name == "glob" || name == "dialect" || name == "stage" || name == "target"
              ? ExpectString(name, value)
              : std::nullopt;
      if (name == "glob") {
        if (!text) {
          ok = false;
        } else if (std::string error = GlobError(*text); !error.empty()) {
          BadValue(value, "invalid glob '" + *text + "': " + error);
          ok = false;
        } else {
          entry.glob = *text;
        }
      } else if (name == "dialect") {
        if (text && !(entry.dialect = ParseDialect(*text))) {
          BadValue(value, "'" + *text + "' is not a dialect; use shadertoy, webgl1 or webgl2");
        }
        ok = ok && entry.dialect.has_value();
      } else if (name == "stage") {
        if (text && !(entry.stage = model::ParseStage(*text))) {
          BadValue(value, "'" + *text + "' is not a stage; use vertex or fragment");
        }
        ok = ok && entry.stage.has_value();
      } else if (name == "target") {
        if (text && !(entry.target = model::ParseTarget(*text))) {
          BadValue(value, "'" + *text + "' is not a target; use webgl1 or webgl2");
        }
        ok = ok && entry.target.has_value();
      } else {
        UnknownKey(name, "[[files]]; expected glob, dialect, stage or target");
      }
    }
    if (ok && entry.glob.empty()) {
      Report(Severity::kError, "config/invalid-value", table.source(),
             "a [[" + std::string(files_key.str()) + "]] entry needs a 'glob'");
      ok = false;
    }
    if (ok) result_.config.files.push_back(std::move(entry));
  }

  const SourceFile& file_;
  ConfigResult result_;
};

}  // namespace

ConfigResult ParseConfig(const SourceFile& file) { return ConfigParser(file).Run(); }

ConfigResult ParseConfig(std::string_view text, std::string_view path, SourceManager& sources) {
  return ParseConfig(sources.Add(std::string(path), std::string(text)));
}

}  // namespace shaderport::driver
