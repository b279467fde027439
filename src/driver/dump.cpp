#include "driver/dump.h"

#include "driver/front_end.h"
#include "driver/read_input.h"

namespace shaderport::driver {

DumpResult DumpFile(const std::filesystem::path& path, DumpKind kind, SourceManager& sources) {
  DumpResult result;
  InputText input = ReadInputFile(path);
  if (!input.text) {
    result.diagnostics.file = &sources.Add(path.string(), "");
    result.diagnostics.diagnostics.push_back(MakeDiagnostic(
        Severity::kError, input.rule_id, {result.diagnostics.file->Id(), 0, 0}, input.message));
    return result;
  }
  const SourceFile& file = sources.Add(path.string(), std::move(*input.text));
  result.diagnostics.file = &file;
  const DetectedKind detected = DetectKind(file.Text(), path);
  result.diagnostics.dialect = std::string(DialectName(detected.dialect));
  result.diagnostics.stage = std::string(StageName(detected.stage));
  FrontEndOptions options;
  options.analyze = kind == DumpKind::kTypes;
  const FrontEndResult front = RunFrontEnd(file, nullptr, detected, sources, options);
  result.diagnostics.diagnostics = front.diagnostics;
  switch (kind) {
    case DumpKind::kTokens:
      result.text = glsl::DumpTokens(file, front.lexed);
      break;
    case DumpKind::kPpTokens:
      result.text = glsl::DumpPpTokens(front.preprocessed, sources);
      break;
    case DumpKind::kAst:
      result.text = glsl::DumpAst(front.parsed.tree, sources);
      break;
    case DumpKind::kTypes:
      result.text = glsl::DumpTypes(front.parsed.tree, *front.model, sources);
      break;
  }
  return result;
}

}  // namespace shaderport::driver
