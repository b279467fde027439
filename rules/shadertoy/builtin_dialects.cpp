#include "rules/shadertoy/builtin_dialects.h"

#include <algorithm>
#include <filesystem>
#include <vector>

#include "base/file_io/read_regular_file.h"
#include "base/limits.h"
#include "rules/shadertoy/embedded_dialects.h"

namespace shaderport::rules {
namespace {

// A dialect TOML as every file that is not an input is read: regular, bounded,
// without blocking on a FIFO.
std::optional<std::string> ReadSmallFile(const std::filesystem::path& path) {
  return file_io::ReadRegularFile(path, limits::kMaxConfigBytes).bytes;
}

std::vector<rule::HarnessDialect> LoadShipped() {
  std::vector<rule::HarnessDialect> dialects;
  for (const EmbeddedTextFile& shipped : EmbeddedDialectFiles()) {
    const SourceFile file(0, "rules/dialects/" + std::string(shipped.name),
                          std::string(shipped.text));
    rule::DialectLoadResult loaded = rule::ParseDialect(file);
    if (loaded.dialect) dialects.push_back(std::move(*loaded.dialect));
  }
  std::sort(dialects.begin(), dialects.end(),
            [](const auto& a, const auto& b) { return a.name < b.name; });
  return dialects;
}

}  // namespace

std::string_view DialectsDirectory() { return SHADERPORT_DIALECTS_DIR; }

std::span<const rule::HarnessDialect> BuiltinDialects() {
  static const std::vector<rule::HarnessDialect> dialects = LoadShipped();
  return dialects;
}

const rule::HarnessDialect* FindBuiltinDialect(std::string_view name) {
  for (const rule::HarnessDialect& dialect : BuiltinDialects()) {
    if (dialect.NameMatches(name)) return &dialect;
  }
  return nullptr;
}

rule::DialectLoadResult LoadDialect(std::string_view name_or_path, SourceManager& sources) {
  if (const rule::HarnessDialect* shipped = FindBuiltinDialect(name_or_path)) {
    return {*shipped, {}};
  }
  rule::DialectLoadResult result;
  const auto text = ReadSmallFile(std::filesystem::path(name_or_path));
  if (!text) {
    Diagnostic diagnostic;
    diagnostic.rule_id = "dialect/not-found";
    diagnostic.message = "'" + std::string(name_or_path) +
                         "' is neither a known dialect (bookofshaders, glslsandbox, "
                         "raymarch-blog, shadertoy) nor a readable dialect file";
    result.diagnostics.push_back(std::move(diagnostic));
    return result;
  }
  return rule::ParseDialect(sources.Add(std::string(name_or_path), *text));
}

}  // namespace shaderport::rules
