#include "rule/harness_dialect_file.h"

#include <filesystem>
#include <string>

#include "base/file_io/read_regular_file.h"
#include "base/limits.h"
#include "model/shipped_dialects.h"

namespace shaderport::rule {

DialectLoadResult ParseDialect(const SourceFile& file) {
  model::DialectParse parsed = model::ParseDialect(file.Text(), file.Name());
  DialectLoadResult result;
  result.dialect = std::move(parsed.dialect);
  for (model::DialectProblem& problem : parsed.problems) {
    result.diagnostics.push_back(MakeDiagnostic(
        problem.error ? Severity::kError : Severity::kWarning, std::move(problem.rule_id),
        {file.Id(), problem.begin, problem.end}, std::move(problem.message)));
  }
  return result;
}

DialectLoadResult LoadDialect(std::string_view name_or_path, SourceManager& sources) {
  if (const model::HarnessDialect* shipped = model::FindBuiltinDialect(name_or_path)) {
    return {*shipped, {}};
  }
  // Read as every file that is not an input is: regular, bounded, without blocking on a FIFO.
  const auto text =
      file_io::ReadRegularFile(std::filesystem::path(name_or_path), limits::kMaxConfigBytes).bytes;
  if (!text) {
    Diagnostic diagnostic;
    diagnostic.rule_id = "dialect/not-found";
    diagnostic.message = "'" + std::string(name_or_path) +
                         "' is neither a known dialect (bookofshaders, glslsandbox, "
                         "raymarch-blog, shadertoy) nor a readable dialect file";
    DialectLoadResult result;
    result.diagnostics.push_back(std::move(diagnostic));
    return result;
  }
  return ParseDialect(sources.Add(std::string(name_or_path), *text));
}

}  // namespace shaderport::rule
