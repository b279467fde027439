#include "driver/port/port_file.h"

#include <algorithm>
#include <memory>
#include <set>
#include <tuple>

#include "driver/file_decision.h"
#include "driver/front_end.h"
#include "driver/read_input.h"
#include "model/shipped_dialects.h"
#include "rule/fix_engine.h"
#include "rule/harness_dialect_detect.h"
#include "rules/registry.h"
#include "validate/glslang_validator.h"
#include "validate/shadertoy_contract.h"

namespace shaderport::driver {
namespace {

// Beyond this many applied fixes, narrowing tries whole rules instead of single fixes.
constexpr size_t kMaxSingleFixTrials = 24;

// What the user said, in the terms of the shared decision (file_decision.h).
DecisionGiven GivenFor(const PortOptions& options) {
  DecisionGiven given;
  given.dialect = options.dialect;
  given.stage = options.stage;
  given.pass = options.pass;
  given.harness = options.harness;
  given.channels = options.channels;
  return given;
}

size_t ErrorCount(const DiagnosticList& diagnostics) {
  return static_cast<size_t>(std::count_if(diagnostics.begin(), diagnostics.end(),
                                           [](auto& d) { return d.severity == Severity::kError; }));
}

class Porter {
 public:
  Porter(const SourceFile& file, const SourceFile* common, const PortOptions& options,
         SourceManager& sources)
      : file_(file), common_(common), options_(options), sources_(sources) {
    decision_ = DecideFile(file, common, GivenFor(options), sources);
    kind_ = decision_.kind;
    if (!decision_.IsShaderToy()) common_ = nullptr;
    rules_ = options.rules;
    if (rules_.empty()) rules_ = rules::RulesForMode(options.mode);
    settings_.mode = options.mode;
    settings_.stage = kind_.stage;
    settings_.harness = decision_.harness;
    settings_.source_version = kind_.dialect == Dialect::kWebGL1 ? 100 : 300;
    settings_.buffer_pass = kind_.pass == model::PassKind::kBuffer;
    for (int i = 0; i < 4; ++i) settings_.channels[i] = options.channels[i];
  }

  PortResult Run() {
    PortResult result;
    result.file = &file_;
    result.kind = kind_;
    result.decision = decision_;
    result.output_stage = kind_.stage;
    rule::FixEngineResult engine = RunEngine({});
    // Text past a resource limit, or fixes that never settled: glslang is not run on
    // it, and the caller writes nothing.
    if (engine.limit_breached || !engine.converged) return Unfinished(std::move(engine), result);
    DiagnosticList validation;
    if (options_.validate && !engine.fixed.empty()) {
      const size_t baseline = ErrorCount(Validate(file_.Text(), /*as_output=*/false));
      validation = Validate(engine.text, IsPort());
      if (ErrorCount(validation) > baseline) {
        engine = Narrow(engine, baseline, validation);
        result.narrowed = true;
      }
    } else if (options_.validate) {
      validation = Validate(engine.text, IsPort());
    }
    result.converged = engine.converged;
    result.text = std::move(engine.text);
    result.map = std::move(engine.map);
    result.rounds = engine.rounds;
    result.fixed = std::move(engine.fixed);
    result.validated = options_.validate && ErrorCount(validation) == 0;
    result.diagnostics = std::move(engine.remaining);
    const DiagnosticList& extra = options_.validate ? validation : engine.front_end;
    for (const Diagnostic& d : extra) {
      result.diagnostics.push_back(rule::MapToOriginal(d, result.map, file_.Id()));
    }
    SortByPosition(result.diagnostics);
    return result;
  }

 private:
  static void SortByPosition(DiagnosticList& diagnostics) {
    std::stable_sort(
        diagnostics.begin(), diagnostics.end(), [](const Diagnostic& a, const Diagnostic& b) {
          return std::tie(a.range.file, a.range.begin) < std::tie(b.range.file, b.range.begin);
        });
  }

  // The input as it was, with the breach or the rules that did not settle.
  PortResult Unfinished(rule::FixEngineResult engine, PortResult& result) {
    result.text = std::string(file_.Text());
    result.map = SourceMap::Identity(static_cast<uint32_t>(result.text.size()));
    result.limit_breached = engine.limit_breached;
    result.converged = engine.converged;
    result.diagnostics = std::move(engine.remaining);
    for (Diagnostic& d : engine.front_end) result.diagnostics.push_back(std::move(d));
    SortByPosition(result.diagnostics);
    return result;
  }

  bool IsPort() const { return options_.mode == rule::PortMode::kPort; }

  rule::FixEngineResult RunEngine(std::function<bool(const Diagnostic&)> allow) {
    rule::FixEngineOptions engine;
    engine.settings = settings_;
    engine.rules = rules_;
    engine.allow_fix = std::move(allow);
    engine.analyze = [this](const SourceFile& current) {
      DetectedKind kind = kind_;
      // Once a port changed the text, it is read as what it has become (WebGL2).
      if (IsPort() && current.Text() != file_.Text()) {
        kind = DetectKind(current.Text(), file_.Name());
        kind.stage = kind_.stage;
      }
      FrontEndOptions front_options;
      front_options.analyze = true;
      front_options.channels = decision_.channels;
      auto front = std::make_shared<FrontEndResult>(
          RunFrontEnd(current, kind.dialect == Dialect::kShaderToy ? common_ : nullptr, kind,
                      sources_, front_options));
      rule::AnalyzedShader shader;
      shader.lexed = &front->lexed;
      shader.preprocessed = &front->preprocessed;
      shader.tree = &front->parsed.tree;
      shader.model = &*front->model;
      shader.diagnostics = front->diagnostics;
      shader.owner = front;
      return shader;
    };
    return rule::RunFixEngine(file_, engine);
  }

  // glslang on `text` (located as the original file): as plain WebGL2 output, or
  // in the original's own dialect.
  DiagnosticList Validate(std::string_view text, bool as_output) {
    const SourceFile current(file_.Id(), file_.Name(), std::string(text));
    validate::ValidationRequest request;
    if (!as_output) {
      request = ComposeForGlslang(decision_, current, common_, sources_);
    } else {
      request.parts.push_back({file_.Name(), current.Text(), file_.Id()});
      request.stage = kind_.stage;
      request.default_version = 100;
    }
    return validate::ValidateWithGlslang(request).diagnostics;
  }

  // The engine run with only the fixes whose key is in `kept`.
  template <typename KeyOf>
  rule::FixEngineResult Attempt(const std::set<std::tuple<std::string, uint32_t, uint32_t>>& kept,
                                const KeyOf& key_of) {
    return RunEngine([&](const Diagnostic& d) { return kept.count(key_of(d)) > 0; });
  }

  // Keeps the applied fixes one at a time (or rule by rule when there are many)
  // as long as they do not add validation errors.
  rule::FixEngineResult Narrow(const rule::FixEngineResult& full, size_t baseline,
                               DiagnosticList& validation) {
    using Key = std::tuple<std::string, uint32_t, uint32_t>;
    const bool by_rule = full.fixed.size() > kMaxSingleFixTrials;
    auto key_of = [by_rule](const Diagnostic& d) {
      return by_rule ? Key{d.rule_id, 0, 0} : Key{d.rule_id, d.range.begin, d.range.end};
    };
    std::vector<Key> units;
    for (const Diagnostic& d : full.fixed) {
      if (std::find(units.begin(), units.end(), key_of(d)) == units.end()) {
        units.push_back(key_of(d));
      }
    }
    // First drop single units from the full set: port fixes depend on each other
    // (#version needs the declared uniforms and main()), so one broken fix is best
    // found by taking it out of the whole, not by building up from nothing.
    std::set<Key> kept(units.begin(), units.end());
    size_t current = ErrorCount(validation);
    for (const Key& unit : units) {
      if (current <= baseline) break;
      std::set<Key> trial = kept;
      trial.erase(unit);
      const size_t errors = ErrorCount(Validate(Attempt(trial, key_of).text, IsPort()));
      if (errors < current) {
        kept = std::move(trial);
        current = errors;
      }
    }
    if (current > baseline) {
      // Still worse than the input: keep units one at a time as long as they do not
      // add errors.
      kept.clear();
      size_t best = baseline;
      for (const Key& unit : units) {
        std::set<Key> trial = kept;
        trial.insert(unit);
        const size_t errors = ErrorCount(Validate(Attempt(trial, key_of).text, IsPort()));
        if (errors <= best) {
          kept = std::move(trial);
          best = errors;
        }
      }
    }
    rule::FixEngineResult narrowed =
        RunEngine([&](const Diagnostic& d) { return kept.count(key_of(d)) > 0; });
    validation = Validate(narrowed.text, IsPort());
    return narrowed;
  }

  const SourceFile& file_;
  const SourceFile* common_;
  const PortOptions& options_;
  SourceManager& sources_;
  FileDecision decision_;
  DetectedKind kind_;
  std::vector<const rule::Rule*> rules_;
  rule::PortSettings settings_;
};

}  // namespace

PortResult PortSource(const SourceFile& file, const SourceFile* common, const PortOptions& options,
                      SourceManager& sources) {
  return Porter(file, common, options, sources).Run();
}

PortResult PortFile(const std::filesystem::path& path, const PortOptions& options,
                    SourceManager& sources) {
  return PortInput(path, ReadInputFile(path), options, sources);
}

PortResult PortInput(const std::filesystem::path& path, InputText input, const PortOptions& options,
                     SourceManager& sources) {
  if (!input.text) {
    PortResult result;
    result.file = &sources.Add(path.string(), "");
    result.read_failed = true;
    Diagnostic error;
    error.rule_id = std::move(input.rule_id);
    error.range = {result.file->Id(), 0, 0};
    error.message = std::move(input.message);
    result.diagnostics.push_back(std::move(error));
    return result;
  }
  const SourceFile& file = sources.Add(path.string(), std::move(*input.text));
  PortResult result = PortSource(file, nullptr, options, sources);
  result.byte_order_mark = input.byte_order_mark;
  return result;
}

PortOptions OptionsFor(const PortOptions& options, const InputFile& input) {
  PortOptions for_input = options;
  if (!for_input.dialect && for_input.harness == nullptr) for_input.dialect = input.dialect;
  if (!for_input.stage) for_input.stage = input.stage;
  return for_input;
}

}  // namespace shaderport::driver
