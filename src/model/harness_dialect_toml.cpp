// Reads a harness dialect from TOML (format: rules/dialects/README.md). Every
// problem is a diagnostic at its line and column; nothing throws out of here.
#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <set>

#include "model/harness_dialect.h"

namespace shaderport::model {
namespace {

// Dialect files are a few KiB; anything much larger is not one.
constexpr size_t kMaxDialectBytes = 1u << 20;

bool IsIdentifier(std::string_view text) {
  if (text.empty() || text.size() > 1024) return false;
  auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  if (!alpha(text[0])) return false;
  return std::all_of(text.begin(), text.end(),
                     [&](char c) { return alpha(c) || (c >= '0' && c <= '9'); });
}

bool IsKnownTypeName(std::string_view type) {
  static const std::set<std::string_view> kTypes = {
      "float",      "int",         "uint",           "bool",
      "vec2",       "vec3",        "vec4",           "ivec2",
      "ivec3",      "ivec4",       "uvec2",          "uvec3",
      "uvec4",      "bvec2",       "bvec3",          "bvec4",
      "mat2",       "mat3",        "mat4",           "mat2x2",
      "mat2x3",     "mat2x4",      "mat3x2",         "mat3x3",
      "mat3x4",     "mat4x2",      "mat4x3",         "mat4x4",
      "sampler2D",  "samplerCube", "sampler3D",      "sampler2DArray",
      "isampler2D", "usampler2D",  "sampler2DShadow"};
  return kTypes.contains(type);
}

// "vec3" or "float[4]": a known type and at most one positive array size.
bool IsValidType(std::string_view type) {
  const size_t bracket = type.find('[');
  if (bracket == std::string_view::npos) return IsKnownTypeName(type);
  if (type.back() != ']' || bracket + 2 >= type.size()) return false;
  const std::string_view size = type.substr(bracket + 1, type.size() - bracket - 2);
  if (size.size() > 4 || size[0] == '0') return false;
  if (!std::all_of(size.begin(), size.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return false;
  }
  return IsKnownTypeName(type.substr(0, bracket));
}

// The first `{word}` of a main() template that is not {entry}, {out} or
// {fresh:NAME}. Other braces are GLSL blocks.
std::optional<std::string> BadPlaceholder(std::string_view body) {
  for (size_t open = body.find('{'); open != std::string_view::npos;
       open = body.find('{', open + 1)) {
    const size_t close = body.find('}', open);
    if (close == std::string_view::npos) break;
    const std::string_view inside = body.substr(open + 1, close - open - 1);
    const bool word = !inside.empty() && std::all_of(inside.begin(), inside.end(), [](char c) {
      return c == ':' || c == '_' || (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') ||
             (c >= 'A' && c <= 'Z');
    });
    if (!word || inside == "entry" || inside == "out") continue;
    if (inside.starts_with("fresh:") && IsIdentifier(inside.substr(6))) continue;
    return std::string(inside);
  }
  return std::nullopt;
}

// Where each 1-based line starts, with "\r\n", "\n" and a lone "\r" ending a line, as
// the SourceFile the caller locates problems in counts them.
std::vector<uint32_t> LineStarts(std::string_view text) {
  std::vector<uint32_t> starts = {0};
  for (uint32_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\r') {
      if (i + 1 < text.size() && text[i + 1] == '\n') ++i;
      starts.push_back(i + 1);
    } else if (text[i] == '\n') {
      starts.push_back(i + 1);
    }
  }
  return starts;
}

class DialectParser {
 public:
  DialectParser(std::string_view text, std::string_view name)
      : text_(text), name_(name), line_starts_(LineStarts(text)) {}

  DialectParse Run() {
    if (text_.size() > kMaxDialectBytes) {
      Error({}, "the dialect file is larger than 1 MiB");
      return Finish();
    }
    toml::table root;
    try {
      root = toml::parse(text_, name_);
    } catch (const toml::parse_error& error) {
      Report(true, "dialect/syntax-error", RangeOf(error.source()),
             "invalid TOML: " + std::string(error.description()));
      return Finish();
    }
    for (auto&& [key, value] : root) ReadTopLevel(key, value);
    if (dialect_.name.empty() && !saw_name_) {
      Report(true, "dialect/missing-key", {0, 0}, "the dialect has no 'name'");
    }
    return Finish();
  }

 private:
  struct Range {
    uint32_t begin = 0;
    uint32_t end = 0;
  };

  DialectParse Finish() {
    // toml++ tables iterate in key order: report in file order instead.
    std::stable_sort(
        result_.problems.begin(), result_.problems.end(),
        [](const DialectProblem& a, const DialectProblem& b) { return a.begin < b.begin; });
    const bool errors = std::any_of(result_.problems.begin(), result_.problems.end(),
                                    [](const DialectProblem& p) { return p.error; });
    if (!errors) result_.dialect = std::move(dialect_);
    return std::move(result_);
  }

  uint32_t LineStart(uint32_t line) const {
    if (line == 0) return 0;
    if (line > line_starts_.size()) return static_cast<uint32_t>(text_.size());
    return line_starts_[line - 1];
  }
  std::string_view LineText(uint32_t line) const {
    if (line == 0 || line > line_starts_.size()) return {};
    const uint32_t begin = line_starts_[line - 1];
    uint32_t end =
        line < line_starts_.size() ? line_starts_[line] : static_cast<uint32_t>(text_.size());
    while (end > begin && (text_[end - 1] == '\n' || text_[end - 1] == '\r')) --end;
    return text_.substr(begin, end - begin);
  }

  // toml++ counts columns in characters; problems are located in bytes.
  uint32_t OffsetOf(const toml::source_position& position) const {
    const uint32_t line_start = LineStart(position.line);
    const std::string_view line = LineText(position.line);
    uint32_t characters = 1;
    size_t i = 0;
    for (; i < line.size() && characters < position.column; ++i) {
      if ((static_cast<unsigned char>(line[i]) & 0xC0) != 0x80) ++characters;
      while (i + 1 < line.size() && (static_cast<unsigned char>(line[i + 1]) & 0xC0) == 0x80) ++i;
    }
    return line_start + static_cast<uint32_t>(i);
  }

  Range RangeOf(const toml::source_region& region) const {
    if (!region.begin) return {0, 0};
    const uint32_t begin = OffsetOf(region.begin);
    const uint32_t end = region.end ? std::max(begin, OffsetOf(region.end)) : begin;
    return {begin, end};
  }

  void Report(bool error, std::string rule, Range range, std::string message) {
    result_.problems.push_back(
        {error, std::move(rule), range.begin, range.end, std::move(message)});
  }
  void Error(const toml::source_region& where, std::string message) {
    Report(true, "dialect/invalid-value", RangeOf(where), std::move(message));
  }
  void UnknownKey(const toml::key& key, std::string_view where) {
    Report(false, "dialect/unknown-key", RangeOf(key.source()),
           "unknown key '" + std::string(key.str()) + "' in " + std::string(where) +
               "; it is ignored");
  }
  void Missing(const toml::node& table, std::string_view key, std::string_view where) {
    Report(true, "dialect/missing-key", RangeOf(table.source()),
           std::string(where) + " needs '" + std::string(key) + "'");
  }

  std::optional<std::string> String(const toml::key& key, const toml::node& node) {
    if (const auto* value = node.as_string()) return value->get();
    Error(node.source(), "'" + std::string(key.str()) + "' must be a string");
    return std::nullopt;
  }
  std::optional<std::string> Identifier(const toml::key& key, const toml::node& node) {
    auto text = String(key, node);
    if (text && !IsIdentifier(*text)) {
      Error(node.source(),
            "'" + std::string(key.str()) + "' must be a GLSL identifier, not '" + *text + "'");
      return std::nullopt;
    }
    return text;
  }
  std::vector<std::string> Strings(const toml::key& key, const toml::node& node) {
    std::vector<std::string> out;
    const toml::array* array = node.as_array();
    if (array == nullptr) {
      Error(node.source(), "'" + std::string(key.str()) + "' must be an array of strings");
      return out;
    }
    for (const toml::node& item : *array) {
      if (auto text = String(key, item)) out.push_back(std::move(*text));
    }
    return out;
  }
  const toml::array* TableArray(const toml::key& key, const toml::node& node) {
    const toml::array* array = node.as_array();
    if (array != nullptr && array->is_array_of_tables()) return array;
    Error(node.source(), "'" + std::string(key.str()) + "' must be an array of tables ([[" +
                             std::string(key.str()) + "]])");
    return nullptr;
  }

  // Only `#version 100` or `#version 300 es` may set the version: it decides the target.
  void ReadPrelude(const toml::key& key, const toml::node& value) {
    auto text = String(key, value);
    if (!text) return;
    dialect_.prelude = std::move(*text);
    if (dialect_.prelude.find("#version") != std::string::npos && dialect_.PreludeVersion() == 0) {
      Error(value.source(), "'prelude' may only say '#version 100' or '#version 300 es'");
    }
  }

  void ReadTopLevel(const toml::key& key, const toml::node& value) {
    if (key == "name") {
      saw_name_ = true;
      auto name = String(key, value);
      if (name && (name->empty() || name->find_first_of(" \t\n/\\") != std::string::npos)) {
        Error(value.source(), "'name' must be a non-empty word such as \"shadertoy\"");
      } else if (name) {
        dialect_.name = std::move(*name);
      }
    } else if (key == "aliases") {
      dialect_.aliases = Strings(key, value);
    } else if (key == "description") {
      if (auto text = String(key, value)) dialect_.description = std::move(*text);
    } else if (key == "declare") {
      auto mode = String(key, value);
      if (mode == "all") {
        dialect_.declare = DeclareMode::kAll;
      } else if (mode == "used") {
        dialect_.declare = DeclareMode::kUsed;
      } else if (mode) {
        Error(value.source(), "'declare' must be \"all\" or \"used\", not '" + *mode + "'");
      }
    } else if (key == "defines") {
      ReadDefines(key, value);
    } else if (key == "hints") {
      dialect_.hints = Strings(key, value);
    } else if (key == "prelude") {
      ReadPrelude(key, value);
    } else if (key == "renames") {
      ReadRenames(key, value);
    } else if (key == "provides") {
      if (const toml::array* array = TableArray(key, value)) {
        for (const toml::node& item : *array) ReadProvided(*item.as_table(), dialect_.provides);
      }
    } else if (key == "entry_points") {
      if (const toml::array* array = TableArray(key, value)) {
        for (const toml::node& item : *array) ReadEntryPoint(*item.as_table());
      }
    } else {
      UnknownKey(key, "the dialect");
    }
  }

  void ReadDefines(const toml::key& key, const toml::node& value) {
    const toml::array* array = value.as_array();
    dialect_.defines = Strings(key, value);
    for (size_t i = 0; array != nullptr && i < dialect_.defines.size(); ++i) {
      const std::string& define = dialect_.defines[i];
      const std::string_view name = std::string_view(define).substr(0, define.find(' '));
      if (!IsIdentifier(name) || define.find('\n') != std::string::npos) {
        Error((*array)[i].source(),
              "a define is \"NAME\" or \"NAME value\" on one line, not '" + define + "'");
      }
    }
  }

  void ReadRenames(const toml::key& key, const toml::node& value) {
    const toml::table* table = value.as_table();
    if (table == nullptr) {
      Error(value.source(), "'renames' must be a table of old = \"new\" names");
      return;
    }
    for (auto&& [from, to] : *table) {
      auto target = Identifier(key, to);
      if (!IsIdentifier(from.str())) {
        Error(from.source(),
              "renamed name '" + std::string(from.str()) + "' must be a GLSL identifier");
      } else if (target) {
        dialect_.renames.emplace_back(std::string(from.str()), std::move(*target));
      }
    }
  }

  void ReadProvided(const toml::table& table, std::vector<ProvidedVariable>& out) {
    ProvidedVariable variable;
    bool has_name = false;
    bool has_type = false;
    for (auto&& [key, value] : table) {
      if (key == "name") {
        has_name = true;  // a bad value is reported once, not also as missing
        if (auto name = Identifier(key, value)) variable.name = std::move(*name);
      } else if (key == "type") {
        has_type = true;
        auto type = String(key, value);
        if (type && !IsValidType(*type)) {
          Error(value.source(), "unknown GLSL type '" + *type +
                                    "' (expected e.g. \"vec3\", \"float[4]\", \"sampler2D\")");
        } else if (type) {
          variable.type = std::move(*type);
        }
      } else if (key == "storage") {
        auto storage = String(key, value);
        if (storage == "uniform") {
          variable.storage = ProvidedStorage::kUniform;
        } else if (storage == "in") {
          variable.storage = ProvidedStorage::kInput;
        } else if (storage == "out") {
          variable.storage = ProvidedStorage::kOutput;
        } else if (storage) {
          Error(value.source(),
                "'storage' must be \"uniform\", \"in\" or \"out\", not '" + *storage + "'");
        }
      } else if (key == "precision") {
        auto precision = String(key, value);
        if (precision == "lowp" || precision == "mediump" || precision == "highp") {
          variable.precision = std::move(*precision);
        } else if (precision) {
          Error(value.source(), "'precision' must be lowp, mediump or highp");
        }
      } else if (key == "description") {
        if (auto description = String(key, value)) variable.description = std::move(*description);
      } else if (key == "in_common_tab") {
        if (const auto* flag = value.as_boolean()) {
          variable.in_common_tab = flag->get();
        } else {
          Error(value.source(), "'in_common_tab' must be true or false");
        }
      } else if (key == "channel") {
        const auto* number = value.as_integer();
        if (number == nullptr || number->get() < 0 || number->get() > 3) {
          Error(value.source(), "'channel' must be an integer from 0 to 3");
        } else {
          variable.channel = static_cast<int>(number->get());
        }
      } else {
        UnknownKey(key, "[[provides]]");
      }
    }
    if (!has_name) return Missing(table, "name", "[[provides]]");
    if (!has_type) return Missing(table, "type", "[[provides]] '" + variable.name + "'");
    if (variable.channel >= 0 && variable.type.rfind("sampler", 0) != 0) {
      Error(table.source(), "channel '" + variable.name + "' must have a sampler type");
    }
    auto named = [&](const ProvidedVariable& v) { return v.name == variable.name; };
    if (std::any_of(dialect_.provides.begin(), dialect_.provides.end(), named) ||
        std::any_of(out.begin(), out.end(), named)) {
      Error(table.source(), "'" + variable.name + "' is provided twice");
    }
    out.push_back(std::move(variable));
  }

  void ReadEntryPoint(const toml::table& table) {
    EntryPoint entry;
    bool has_function = false;
    bool has_main = false;
    for (auto&& [key, value] : table) {
      if (key == "function") {
        has_function = true;
        if (auto name = Identifier(key, value)) entry.function = std::move(*name);
      } else if (key == "main") {
        if (auto body = String(key, value)) entry.main_body = std::move(*body), has_main = true;
      } else if (key == "buffer_main") {
        if (auto body = String(key, value)) entry.buffer_main_body = std::move(*body);
      } else if (key == "output") {
        if (auto name = Identifier(key, value)) entry.output_name = std::move(*name);
      } else if (key == "provides") {
        if (const toml::array* array = TableArray(key, value)) {
          for (const toml::node& item : *array) ReadProvided(*item.as_table(), entry.provides);
        }
      } else {
        UnknownKey(key, "[[entry_points]]");
      }
    }
    if (!has_function) return Missing(table, "function", "[[entry_points]]");
    if (!has_main) return Missing(table, "main", "[[entry_points]] '" + entry.function + "'");
    for (const std::string* body : {&entry.main_body, &entry.buffer_main_body}) {
      if (auto bad = BadPlaceholder(*body)) {
        Error(table.source(), "unknown placeholder '{" + *bad + "}' in main of '" + entry.function +
                                  "' (use {entry}, {out} or {fresh:NAME})");
      }
    }
    if (entry.function == "main") {
      Error(table.source(), "the entry point is the function the user writes instead of main()");
    }
    dialect_.entry_points.push_back(std::move(entry));
  }

  std::string_view text_;
  std::string_view name_;
  std::vector<uint32_t> line_starts_;
  HarnessDialect dialect_;
  DialectParse result_;
  bool saw_name_ = false;
};

}  // namespace

DialectParse ParseDialect(std::string_view text, std::string_view name) {
  return DialectParser(text, name).Run();
}

}  // namespace shaderport::model
