#include "report/merge.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

namespace shaderport {
namespace {

using Json = nlohmann::ordered_json;

// The formats' own serialisation (FormatJson, FormatSarif): parsing and dumping
// again gives the same bytes.
std::string Dump(const Json& json) {
  return json.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

std::optional<Severity> SeverityOfLevel(const Json& level) {
  if (!level.is_string()) return std::nullopt;
  return SeverityFromName(level.get<std::string>());
}

void NoteSeverity(std::optional<Severity>& worst, std::optional<Severity> severity) {
  if (severity && (!worst || *severity > *worst)) worst = severity;
}

struct ParsedInput {
  const MergeInput* input = nullptr;
  Json json;
  MergeFormat format = MergeFormat::kJson;
  std::string version;  // the tool's
};

bool IsObjectWith(const Json& json, const char* key) {
  return json.is_object() && json.contains(key);
}

// The shape every later step relies on, so that no step indexes a member that is
// not there (const operator[] on a missing key is undefined) or of another type.
// Members of the wrong type deeper down throw, and MergeReports reports that.
std::optional<MergeFormat> FormatOf(const Json& json) {
  if (!json.is_object()) return std::nullopt;
  if (json.contains("runs") && json.contains("$schema")) {
    const Json& runs = json["runs"];
    if (!runs.is_array() || runs.size() != 1 || !IsObjectWith(runs[0], "tool") ||
        !IsObjectWith(runs[0]["tool"], "driver") || !runs[0]["tool"]["driver"].is_object()) {
      return std::nullopt;
    }
    return MergeFormat::kSarif;
  }
  if (json.contains("files") && json.contains("summary") && json["summary"].is_object()) {
    return MergeFormat::kJson;
  }
  return std::nullopt;
}

std::string ToolVersion(const Json& json, MergeFormat format) {
  const Json* tool = nullptr;
  if (format == MergeFormat::kJson) {
    tool = json.contains("tool") ? &json["tool"] : nullptr;
  } else if (json["runs"].is_array() && json["runs"].size() == 1 &&
             json["runs"][0].contains("tool") && json["runs"][0]["tool"].contains("driver")) {
    tool = &json["runs"][0]["tool"]["driver"];
  }
  if (tool == nullptr || !tool->is_object()) return {};
  const auto name = tool->find("name");
  if (name == tool->end() || *name != "shaderport") return {};  // compared, never converted
  const Json version = tool->value("version", Json());
  return version.is_string() ? version.get<std::string>() : std::string();
}

// --- shards ----------------------------------------------------------------

Json* ShardSpecOf(Json& json, MergeFormat format) {
  if (format == MergeFormat::kJson) return json.contains("shard") ? &json["shard"] : nullptr;
  Json& run = json["runs"][0];
  if (!run.contains("properties") || !IsObjectWith(run["properties"], kSarifShardSpecProperty)) {
    return nullptr;
  }
  return &run["properties"][kSarifShardSpecProperty];
}

std::optional<ShardOfRun> ParseSpec(const Json& spec) {
  if (!spec.is_string()) return std::nullopt;
  const std::string text = spec.get<std::string>();
  unsigned index = 0, count = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%u/%u%c", &index, &count, &tail) != 2) return std::nullopt;
  if (index < 1 || index > count) return std::nullopt;
  return ShardOfRun{index, count};
}

// All inputs are shards of one split, each shard exactly once, or none is a
// shard. Removes the markers: the merged report is what one run prints.
bool CheckShardSet(std::vector<ParsedInput>& inputs, MergeFormat format, MergeResult& result) {
  std::map<unsigned, std::string> seen;  // shard index -> input name
  std::optional<unsigned> count;
  size_t marked = 0;
  for (ParsedInput& input : inputs) {
    Json* spec = ShardSpecOf(input.json, format);
    if (spec == nullptr) continue;
    ++marked;
    const std::optional<ShardOfRun> shard = ParseSpec(*spec);
    if (!shard) {
      result.errors.push_back(input.input->name + ": a broken shard marker");
      return false;
    }
    if (count && *count != shard->count) {
      result.errors.push_back(input.input->name + ": shard " + spec->get<std::string>() +
                              " is not one of " + std::to_string(*count) + " shards");
      return false;
    }
    count = shard->count;
    const auto [it, inserted] = seen.emplace(shard->index, input.input->name);
    if (!inserted) {
      result.errors.push_back(input.input->name + ": shard " + spec->get<std::string>() +
                              " is also in " + it->second);
      return false;
    }
    if (format == MergeFormat::kJson) {
      input.json.erase("shard");
    } else {
      input.json["runs"][0]["properties"].erase(kSarifShardSpecProperty);
    }
  }
  if (marked == 0) return true;
  if (marked != inputs.size()) {
    result.errors.push_back("outputs of check --shard mixed with other outputs");
    return false;
  }
  std::string missing;
  for (unsigned index = 1; index <= *count; ++index) {
    if (seen.contains(index)) continue;
    missing += (missing.empty() ? "" : ", ") + std::to_string(index) + "/" + std::to_string(*count);
  }
  if (!missing.empty()) {
    result.errors.push_back("shard " + missing + " missing: the merged report would leave " +
                            "out its files");
    return false;
  }
  return true;
}

// --- JSON ------------------------------------------------------------------

// A report's own entries for a .shaderport.toml or a project document (whose tabs
// are `doc.json#Tab`) hold findings about inputs, not checked files (FileRole).
bool IsCheckedFile(const Json& file) {
  const std::filesystem::path path(file["path"].get<std::string>());
  const std::string extension = path.extension().string();
  return path.filename() != ".shaderport.toml" && extension != ".json" && extension != ".jsonl";
}

bool MergeJson(std::vector<ParsedInput>& inputs, MergeResult& result) {
  // Each file once (a config file's own findings appear in every shard that
  // used it), then in path order as SortReport leaves them.
  std::vector<Json> files;
  std::map<std::string, bool> seen;
  for (ParsedInput& input : inputs) {
    Json& list = input.json["files"];
    if (!list.is_array() || input.json.value("version", Json()) != inputs[0].json["version"]) {
      result.errors.push_back(input.input->name + ": not a shaderport JSON report of this version");
      return false;
    }
    for (Json& file : list) {
      if (!file.is_object() || !file.contains("path") || !file["path"].is_string() ||
          !file.contains("diagnostics") || !file["diagnostics"].is_array()) {
        result.errors.push_back(input.input->name + ": a file entry without path or diagnostics");
        return false;
      }
      if (seen.emplace(file["path"].get<std::string>(), true).second) {
        files.push_back(std::move(file));
      }
    }
  }
  std::stable_sort(files.begin(), files.end(), [](const Json& a, const Json& b) {
    return a["path"].get_ref<const std::string&>() < b["path"].get_ref<const std::string&>();
  });
  size_t errors = 0, warnings = 0, notes = 0, with_problems = 0, fixable = 0;
  for (const Json& file : files) {
    if (!file["diagnostics"].empty()) ++with_problems;
    for (const Json& diagnostic : file["diagnostics"]) {
      const std::optional<Severity> severity =
          SeverityOfLevel(diagnostic.value("severity", Json()));
      NoteSeverity(result.worst, severity);
      if (severity == Severity::kError) ++errors;
      if (severity == Severity::kWarning) ++warnings;
      if (severity == Severity::kNote) ++notes;
      if (diagnostic.value("fixable", false)) ++fixable;
    }
  }
  Json merged = std::move(inputs[0].json);
  Json& summary = merged["summary"];
  summary["errors"] = errors;
  summary["warnings"] = warnings;
  summary["notes"] = notes;
  summary["filesWithProblems"] = with_problems;
  summary["filesChecked"] = std::count_if(files.begin(), files.end(), IsCheckedFile);
  summary["fixable"] = fixable;
  merged["files"] = std::move(files);
  result.output = Dump(merged);
  return true;
}

// --- SARIF -----------------------------------------------------------------

// The results of one checked file, as a run of consecutive results of one input.
struct ResultBlock {
  std::string name;  // the sort key: the file's name as SortReport orders it
  std::vector<Json> results;
};

// Where a result points: the owner of results written without the shard index.
std::string LocationKey(const Json& result) {
  const Json& locations = result.value("locations", Json::array());
  if (!locations.is_array() || locations.empty()) return {};
  const Json& artifact = locations[0]
                             .value("physicalLocation", Json::object())
                             .value("artifactLocation", Json::object());
  return artifact.value("uri", std::string());
}

bool SplitBlocks(ParsedInput& input, std::vector<ResultBlock>& blocks, MergeResult& result) {
  Json& run = input.json["runs"][0];
  Json& results = run["results"];
  if (!results.is_array()) {
    result.errors.push_back(input.input->name + ": a SARIF run without results");
    return false;
  }
  const Json* index = nullptr;
  if (run.contains("properties") && run["properties"].contains(kSarifShardProperty)) {
    index = &run["properties"][kSarifShardProperty];
  }
  if (index == nullptr) {
    // Not a shard: results are grouped by the file they point at.
    for (Json& entry : results) {
      std::string key = LocationKey(entry);
      if (blocks.empty() || blocks.back().name != key) blocks.push_back({std::move(key), {}});
      blocks.back().results.push_back(std::move(entry));
    }
    return true;
  }
  size_t next = 0;
  for (const Json& file : *index) {
    const Json name = file.value("name", Json());
    const Json count = file.value("results", Json());
    if (!name.is_string() || !count.is_number_unsigned() ||
        count.get<size_t>() > results.size() - next) {
      result.errors.push_back(input.input->name + ": a broken " + kSarifShardProperty + " index");
      return false;
    }
    ResultBlock block{name.get<std::string>(), {}};
    for (size_t i = 0; i < count.get<size_t>(); ++i) {
      block.results.push_back(std::move(results[next++]));
    }
    blocks.push_back(std::move(block));
  }
  if (next != results.size()) {
    result.errors.push_back(input.input->name + ": the " + std::string(kSarifShardProperty) +
                            " index does not cover every result");
    return false;
  }
  return true;
}

// "<16 hex digits>:<occurrence>": the occurrence is renumbered over the merged report.
bool IsOccurrenceFingerprint(const std::string& value) {
  const size_t colon = value.find(':');
  return colon == 16 && value.size() > 17 && value.find_first_not_of("0123456789abcdef") == colon &&
         value.find_first_not_of("0123456789", colon + 1) == std::string::npos;
}

bool MergeSarif(std::vector<ParsedInput>& inputs, MergeResult& result) {
  std::map<std::string, Json> rules;  // sorted by id: the single run's rules[] order
  std::vector<std::vector<ResultBlock>> blocks(inputs.size());
  size_t indexed = 0;
  for (size_t i = 0; i < inputs.size(); ++i) {
    ParsedInput& input = inputs[i];
    const Json& run = input.json["runs"][0];
    const Json& driver = run["tool"]["driver"];
    for (const Json& rule : driver.value("rules", Json::array())) {
      const std::string id = rule.value("id", std::string());
      auto [it, inserted] = rules.emplace(id, rule);
      // A rule's default level is the most severe level of its results in the run.
      const Json level = rule.value("defaultConfiguration", Json::object()).value("level", Json());
      const Json kept =
          it->second.value("defaultConfiguration", Json::object()).value("level", Json());
      if (!inserted && SeverityOfLevel(level) > SeverityOfLevel(kept)) it->second = rule;
    }
    if (run.contains("properties") && run["properties"].contains(kSarifShardProperty)) ++indexed;
    if (!SplitBlocks(input, blocks[i], result)) return false;
  }
  if (indexed != 0 && indexed != inputs.size()) {
    result.errors.push_back("outputs of check --shard mixed with other SARIF outputs");
    return false;
  }
  // A merge of sorted lists keeps each input's own order; each file's results are
  // taken once (a config file's own findings appear in every shard that used it).
  std::vector<ResultBlock> ordered;
  std::vector<size_t> next(inputs.size(), 0);
  std::map<std::string, size_t> taken_from;
  while (true) {
    std::optional<size_t> pick;
    for (size_t i = 0; i < inputs.size(); ++i) {
      if (next[i] == blocks[i].size()) continue;
      if (!pick || blocks[i][next[i]].name < blocks[*pick][next[*pick]].name) pick = i;
    }
    if (!pick) break;
    ResultBlock& block = blocks[*pick][next[*pick]++];
    const auto [first, inserted] = taken_from.emplace(block.name, *pick);
    if (!inserted && first->second != *pick) continue;
    ordered.push_back(std::move(block));
  }
  std::map<std::string, size_t> rule_index;
  Json rule_table = Json::array();
  for (auto& [id, rule] : rules) {
    rule_index[id] = rule_table.size();
    rule_table.push_back(std::move(rule));
  }
  Json results = Json::array();
  std::map<std::string, int> occurrences;
  for (ResultBlock& block : ordered) {
    for (Json& entry : block.results) {
      const std::string id = entry.value("ruleId", std::string());
      if (!rule_index.contains(id)) {
        result.errors.push_back("a result of rule '" + id + "' that no rule table lists");
        return false;
      }
      entry["ruleIndex"] = rule_index[id];
      NoteSeverity(result.worst, SeverityOfLevel(entry.value("level", Json("warning"))));
      if (entry.contains("partialFingerprints")) {
        for (auto& [key, value] : entry["partialFingerprints"].items()) {
          if (!value.is_string() || !IsOccurrenceFingerprint(value.get<std::string>())) continue;
          const std::string hash = value.get<std::string>().substr(0, 16);
          value = hash + ":" + std::to_string(++occurrences[key + '\n' + hash]);
        }
      }
      results.push_back(std::move(entry));
    }
  }
  Json merged = std::move(inputs[0].json);
  Json& run = merged["runs"][0];
  run["tool"]["driver"]["rules"] = std::move(rule_table);
  run["results"] = std::move(results);
  if (run.contains("properties")) {
    run["properties"].erase(kSarifShardProperty);
    if (run["properties"].empty()) run.erase("properties");
  }
  result.output = Dump(merged);
  return true;
}

}  // namespace

namespace {

MergeResult MergeReportsOrThrow(const std::vector<MergeInput>& inputs,
                                std::optional<MergeFormat> format) {
  MergeResult result;
  if (inputs.empty()) {
    result.errors.push_back("no reports to merge");
    return result;
  }
  std::vector<ParsedInput> parsed;
  for (const MergeInput& input : inputs) {
    ParsedInput entry;
    entry.input = &input;
    entry.json = Json::parse(input.text, nullptr, false);
    const std::optional<MergeFormat> found = FormatOf(entry.json);
    if (entry.json.is_discarded() || !found) {
      result.errors.push_back(input.name + ": not a JSON or SARIF report of shaderport check");
      continue;
    }
    entry.format = *found;
    entry.version = ToolVersion(entry.json, entry.format);
    if (entry.version.empty()) {
      result.errors.push_back(input.name + ": not written by shaderport");
      continue;
    }
    if (!format) format = entry.format;
    if (entry.format != *format) {
      result.errors.push_back(
          input.name + ": a " + (entry.format == MergeFormat::kSarif ? "SARIF" : "JSON") +
          " report among " + (*format == MergeFormat::kSarif ? "SARIF" : "JSON") + " reports");
      continue;
    }
    if (!parsed.empty() && entry.version != parsed[0].version) {
      result.errors.push_back(input.name + ": written by shaderport " + entry.version + ", not " +
                              parsed[0].version);
      continue;
    }
    parsed.push_back(std::move(entry));
  }
  if (!result.errors.empty()) return result;
  if (!CheckShardSet(parsed, *format, result)) return result;
  const bool merged =
      *format == MergeFormat::kJson ? MergeJson(parsed, result) : MergeSarif(parsed, result);
  if (!merged) {
    result.output.clear();
    result.worst.reset();
  }
  return result;
}

}  // namespace

MergeResult MergeReports(const std::vector<MergeInput>& inputs, std::optional<MergeFormat> format) {
  // A report that has the right outline but a member of the wrong type deeper down
  // (a rule id that is a number) is the user's input, not an internal error.
  try {
    return MergeReportsOrThrow(inputs, format);
  } catch (const nlohmann::json::exception& error) {
    MergeResult result;
    result.errors.push_back(std::string("not a report this shaderport can merge: ") + error.what());
    return result;
  }
}

std::string AddShardMarkers(std::string_view output, MergeFormat format, const CheckReport& report,
                            ShardOfRun shard) {
  Json json = Json::parse(output, nullptr, false);
  const std::string spec = std::to_string(shard.index) + "/" + std::to_string(shard.count);
  if (format == MergeFormat::kJson) {
    if (json.is_discarded() || !json.is_object()) return std::string(output);
    json["shard"] = spec;
    return Dump(json);
  }
  if (json.is_discarded() || !json.contains("runs") || json["runs"].empty()) {
    return std::string(output);
  }
  json["runs"][0]["properties"][kSarifShardSpecProperty] = spec;
  Json files = Json::array();
  for (const FileReport& file : report.files) {
    if (file.diagnostics.empty()) continue;
    files.push_back({{"name", file.file != nullptr ? file.file->Name() : std::string()},
                     {"results", file.diagnostics.size()}});
  }
  json["runs"][0]["properties"][kSarifShardProperty] = std::move(files);
  return Dump(json);
}

}  // namespace shaderport
