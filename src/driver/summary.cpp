#include "driver/summary.h"

#include "driver/front_end.h"
#include "driver/input_files.h"
#include "driver/parallel_for.h"
#include "driver/read_input.h"

namespace shaderport::driver {
namespace {

SummaryRow SummarizeFile(const std::filesystem::path& path) {
  SummaryRow row;
  row.path = path.string();
  InputText input = ReadInputFile(path);
  if (!input.text) {
    row.problem = input.rule_id;
    return row;
  }
  SourceManager sources;
  const SourceFile& file = sources.Add(path.string(), std::move(*input.text));
  const DetectedKind kind = DetectKind(file.Text(), path);
  row.dialect = std::string(DialectName(kind.dialect));
  row.stage = std::string(StageName(kind.stage));
  row.bytes = file.Text().size();
  FrontEndOptions options;
  options.analyze = true;
  const FrontEndResult front = RunFrontEnd(file, nullptr, kind, sources, options);
  row.tokens = front.lexed.tokens.size() - 1;  // the end-of-file token is not a token of the file
  const glsl::SyntaxTree& tree = front.parsed.tree;
  row.nodes = tree.NodeCount();
  for (uint32_t id = 0; id < tree.NodeCount(); ++id) {
    if (!tree.NodeAt(id).IsExpr()) continue;
    ++row.expressions;
    if (!front.model->TypeOf(id).IsUnknown()) ++row.typed;
  }
  row.mismatches = front.model->mismatches.size();
  for (const Diagnostic& diagnostic : front.diagnostics) {
    if (diagnostic.severity == Severity::kError) ++row.errors;
  }
  return row;
}

}  // namespace

std::vector<SummaryRow> Summarize(const std::vector<std::filesystem::path>& paths, unsigned jobs,
                                  std::vector<std::string>& path_errors) {
  const InputFileList inputs = CollectInputFiles(paths);
  path_errors = inputs.errors;
  std::vector<SummaryRow> rows(inputs.files.size());
  ParallelFor(rows.size(), jobs, [&](size_t i) { rows[i] = SummarizeFile(inputs.files[i]); });
  return rows;
}

}  // namespace shaderport::driver
