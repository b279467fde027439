#include "driver/project/load_document.h"

namespace shaderport::driver::project {

LoadedDocument LoadDocument(const std::filesystem::path& path, InputText input,
                            SourceManager& sources) {
  LoadedDocument out;
  const std::string name = path.string();
  if (!input.text) {
    out.document = &sources.Add(name, "");
    out.problems.push_back(MakeDiagnostic(Severity::kError, std::move(input.rule_id),
                                          {out.document->Id(), 0, 0}, std::move(input.message)));
    return out;
  }
  out.document = &sources.Add(name, std::move(*input.text));
  const std::string_view text = out.document->Text();
  *out.read = path.extension() == ".jsonl" ? ReadShaderToyJsonLines(text) : ReadShaderToyJson(text);
  for (const ProjectProblem& problem : out.read->problems) {
    out.problems.push_back(MakeDiagnostic(Severity::kError, "input/invalid-project",
                                          {out.document->Id(), problem.offset, problem.offset},
                                          problem.message));
  }
  if (out.read->projects.empty() && out.read->problems.empty()) {
    out.problems.push_back(MakeDiagnostic(Severity::kError, "input/invalid-project",
                                          {out.document->Id(), 0, 0},
                                          "the file holds no ShaderToy project"));
  }
  return out;
}

}  // namespace shaderport::driver::project
