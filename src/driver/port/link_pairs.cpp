#include "driver/port/link_pairs.h"

#include <filesystem>
#include <map>
#include <string>

#include "validate/stage_link.h"

namespace shaderport::driver {

size_t LinkPortedPairs(std::vector<PortResult>& results) {
  struct Pair {
    PortResult* vertex = nullptr;
    PortResult* fragment = nullptr;
  };
  std::map<std::string, Pair> pairs;  // ordered: reports come out the same every run
  for (PortResult& result : results) {
    if (result.read_failed || result.file == nullptr || !result.validated) continue;
    const std::filesystem::path path(result.file->Name());
    Pair& pair = pairs[(path.parent_path() / path.stem()).string()];
    (result.output_stage == model::Stage::kVertex ? pair.vertex : pair.fragment) = &result;
  }
  size_t linked = 0;
  for (auto& [stem, pair] : pairs) {
    if (pair.vertex == nullptr || pair.fragment == nullptr) continue;
    const validate::StageLinkResult link =
        validate::LinkStages(pair.vertex->text, pair.fragment->text);
    ++linked;
    if (link.linked) continue;
    std::string log = link.log;
    while (!log.empty() && log.back() == '\n') log.pop_back();
    pair.fragment->diagnostics.push_back(MakeDiagnostic(
        Severity::kError, "port/stages-do-not-link", {pair.fragment->file->Id(), 0, 0},
        "the ported shader does not link with '" + pair.vertex->file->Name() + "': " + log));
  }
  return linked;
}

}  // namespace shaderport::driver
