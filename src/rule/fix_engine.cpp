#include "rule/fix_engine.h"

#include <algorithm>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "diag/limit_breach.h"
#include "glsl/syntax/parser.h"
#include "rule/fix_selection.h"

namespace shaderport::rule {
namespace {

struct PlainAnalysis {
  glsl::LexedFile lexed;
  glsl::PreprocessResult preprocessed;
  glsl::ParseResult parsed;
  glsl::SemanticModel model;
};

SourceRange MapRange(const SourceRange& range, const SourceMap& map, FileId file) {
  if (range.file != file) return range;
  const auto [begin, end] = map.ToOriginalRange(range.begin, range.end);
  return {file, begin, end};
}

// Runs every rule on one analysed text; diagnostics come back in registry order.
DiagnosticList RunRules(const SourceFile& file, const AnalyzedShader& analysis,
                        const FixEngineOptions& options) {
  DiagnosticList all;
  for (const Rule* rule : options.rules) {
    RuleContext context(file, *analysis.lexed, *analysis.preprocessed, *analysis.tree,
                        *analysis.model, options.settings);
    try {
      rule->Run(context);
    } catch (const std::exception& e) {
      Diagnostic failure;
      failure.rule_id = "internal/error";
      failure.range = {file.Id(), 0, 0};
      failure.message = "rule '" + std::string(rule->Info().id) + "' failed: " + e.what();
      context.Report(std::move(failure));
    }
    for (Diagnostic& d : context.TakeDiagnostics()) {
      if (d.rule_id.empty()) d.rule_id = std::string(rule->Info().id);
      all.push_back(std::move(d));
    }
  }
  return all;
}

// Sorted, without repeats, joined by ", ".
std::string JoinedRuleIds(std::vector<std::string> ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  std::string joined;
  for (const std::string& id : ids) joined += (joined.empty() ? "" : ", ") + id;
  return joined;
}

// Why the engine stopped while rules still wanted edits.
std::string StopMessage(int max_rounds, int cycle_rounds,
                        const std::vector<std::vector<std::string>>& rules_by_round,
                        const DiagnosticList& found, const std::vector<size_t>& applied) {
  std::vector<std::string> ids;
  ids.reserve(applied.size());
  for (size_t i : applied) ids.push_back(found[i].rule_id);
  if (cycle_rounds > 0) {
    // Only the rounds inside the cycle: the rules that keep undoing each other.
    const size_t first = rules_by_round.size() - static_cast<size_t>(cycle_rounds);
    for (size_t r = first; r < rules_by_round.size(); ++r) {
      ids.insert(ids.end(), rules_by_round[r].begin(), rules_by_round[r].end());
    }
    return "rules undo each other's fixes (the text came back to what it was " +
           std::to_string(cycle_rounds) + " round" + (cycle_rounds == 1 ? "" : "s") +
           " earlier): " + JoinedRuleIds(std::move(ids));
  }
  for (const auto& round : rules_by_round) ids.insert(ids.end(), round.begin(), round.end());
  return "rules still wanted changes after " + std::to_string(max_rounds) +
         " rounds: " + JoinedRuleIds(std::move(ids));
}

// The text `result` holds breached a resource limit: no rule runs on it. The input
// itself is handed back unchanged; a text the fixes made is not to be used.
void StopAtLimit(const AnalyzedShader& analysis, FileId id,
                 const std::vector<std::vector<std::string>>& rules_by_round,
                 FixEngineResult& result) {
  result.limit_breached = true;
  for (const Diagnostic& d : LimitBreaches(analysis.diagnostics)) {
    result.front_end.push_back(MapToOriginal(d, result.map, id));
  }
  if (rules_by_round.empty()) return;
  std::vector<std::string> ids;
  for (const auto& round : rules_by_round) ids.insert(ids.end(), round.begin(), round.end());
  result.converged = false;
  Diagnostic stop;
  stop.rule_id = "internal/error";
  stop.range = {id, 0, 0};
  stop.message = "fixes made the text exceed a resource limit (docs/limits.md): " +
                 JoinedRuleIds(std::move(ids));
  result.remaining.push_back(std::move(stop));
}

}  // namespace

AnalyzedShader AnalyzePlain(const SourceFile& file, int version, model::Stage stage,
                            std::vector<std::string> predefined) {
  auto analysis = std::make_shared<PlainAnalysis>();
  analysis->lexed = glsl::Lex(file);
  const SourceFile* files[] = {&file};
  glsl::PreprocessOptions pp_options;
  pp_options.predefined = std::move(predefined);
  analysis->preprocessed = glsl::Preprocess(files, pp_options);
  glsl::ParseOptions parse_options;
  parse_options.version = version != 0 ? version : analysis->preprocessed.version.number;
  analysis->parsed = glsl::Parse(analysis->preprocessed, parse_options);
  glsl::AnalyzeOptions analyze_options;
  analyze_options.version = parse_options.version;
  analyze_options.stage = stage;
  analysis->model = glsl::Analyze(analysis->parsed.tree, analyze_options);

  AnalyzedShader shader;
  shader.lexed = &analysis->lexed;
  shader.preprocessed = &analysis->preprocessed;
  shader.tree = &analysis->parsed.tree;
  shader.model = &analysis->model;
  shader.diagnostics = analysis->lexed.diagnostics;
  for (const auto* list : {&analysis->preprocessed.diagnostics, &analysis->parsed.diagnostics}) {
    shader.diagnostics.insert(shader.diagnostics.end(), list->begin(), list->end());
  }
  shader.owner = analysis;
  return shader;
}

Diagnostic MapToOriginal(Diagnostic diagnostic, const SourceMap& map, FileId file) {
  diagnostic.range = MapRange(diagnostic.range, map, file);
  for (DiagnosticNote& note : diagnostic.notes) note.range = MapRange(note.range, map, file);
  std::vector<FixIt> kept;
  for (FixIt& fix : diagnostic.fixes) {
    if (fix.range.file == file && !map.IsCopied(fix.range.begin, fix.range.end)) continue;
    fix.range = MapRange(fix.range, map, file);
    kept.push_back(std::move(fix));
  }
  diagnostic.fixes = std::move(kept);
  return diagnostic;
}

FixEngineResult RunFixEngine(const SourceFile& original, const FixEngineOptions& options) {
  const Analyzer analyze = options.analyze ? options.analyze : [&](const SourceFile& file) {
    return AnalyzePlain(file, 0, options.settings.stage);
  };
  const FileId id = original.Id();
  FixEngineResult result;
  result.text = std::string(original.Text());
  result.map = SourceMap::Identity(static_cast<uint32_t>(result.text.size()));

  // Hashes of the text at the start of each round: a text seen before means the
  // rules are cycling, which no number of further rounds would end.
  std::vector<size_t> seen;
  std::vector<std::vector<std::string>> rules_by_round;
  for (int round = 0;; ++round) {
    const size_t hash = std::hash<std::string>{}(result.text);
    const auto earlier = std::find(seen.begin(), seen.end(), hash);
    const int cycle_rounds = earlier == seen.end() ? 0 : static_cast<int>(seen.end() - earlier);
    seen.push_back(hash);
    // The edited text keeps the original's id: its ranges are mapped back below.
    const SourceFile current(id, original.Name(), result.text);
    const AnalyzedShader analysis = analyze(current);
    if (HasLimitBreach(analysis.diagnostics)) {
      StopAtLimit(analysis, id, rules_by_round, result);
      return result;
    }
    DiagnosticList found = RunRules(current, analysis, options);

    FixSelectionOptions selection_options;
    selection_options.file = id;
    selection_options.apply_suggestions = options.apply_suggestions;
    selection_options.refused_note = options.refused_note;
    if (options.allow_fix) {
      selection_options.allow = [&](const Diagnostic& d) {
        return options.allow_fix(MapToOriginal(d, result.map, id));
      };
    }
    const FixSelection selection = SelectFixes(found, selection_options);
    const bool stop = round >= options.max_rounds || cycle_rounds > 0;
    std::optional<EditResult> edited;
    if (!selection.edits.empty() && !stop) edited = ApplyEdits(result.text, selection.edits);

    if (!edited) {
      if (!selection.edits.empty()) {
        result.converged = !stop;
        Diagnostic fight;
        fight.rule_id = "internal/error";
        fight.range = {id, 0, 0};
        fight.message = stop ? StopMessage(options.max_rounds, cycle_rounds, rules_by_round, found,
                                           selection.applied)
                             : "the chosen fixes could not be applied";
        result.remaining.push_back(fight);
      }
      for (Diagnostic& d : found) result.remaining.push_back(MapToOriginal(d, result.map, id));
      for (const Diagnostic& d : analysis.diagnostics) {
        result.front_end.push_back(MapToOriginal(d, result.map, id));
      }
      return result;
    }
    rules_by_round.emplace_back();
    for (size_t i : selection.applied) {
      rules_by_round.back().push_back(found[i].rule_id);
      // Its fixes, located in the original, stay: check attaches them to the findings
      // they repair (MapToOriginal keeps only those that edit the original's own text).
      result.fixed.push_back(MapToOriginal(found[i], result.map, id));
    }
    result.map = SourceMap::Compose(result.map, edited->map);
    result.text = std::move(edited->text);
    ++result.rounds;
  }
}

}  // namespace shaderport::rule
