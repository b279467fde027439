#include "driver/check_file.h"

#include <chrono>
#include <string_view>
#include <utility>
#include <vector>

#include "base/limits.h"
#include "diag/limit_breach.h"
#include "driver/channel_notes.h"
#include "driver/dialect.h"
#include "driver/file_decision.h"
#include "driver/fixable_findings.h"
#include "driver/front_end.h"
#include "driver/project/record_json.h"
#include "driver/project/shadertoy_project.h"
#include "driver/read_input.h"
#include "driver/render_check/render_file.h"
#include "driver/render_check/render_multipass.h"
#include "driver/suppress/suppressions.h"
#include "driver/webgl_checks.h"
#include "validate/glslang_validator.h"
#include "validate/shadertoy_contract.h"

namespace shaderport::driver {
namespace {

// What the user said about the file: flags over its .shaderport.toml entry, and a
// project's own tab and inputs.
DecisionGiven GivenFor(const FileJob& job, const CheckOptions& options) {
  DecisionGiven given;
  if (job.config != nullptr) {
    const FileSettings settings = SettingsFor(*job.config, job.absolute_path);
    const std::string from = "[[files]] in " + (job.config->directory / kConfigFileName).string();
    given.dialect = settings.dialect;
    given.stage = settings.stage;
    given.target = settings.target;
    given.dialect_from = given.stage_from = given.target_from = from;
  }
  if (options.dialect) {
    given.dialect = options.dialect;
    given.dialect_from = "--dialect";
  }
  if (options.stage) {
    given.stage = options.stage;
    given.stage_from = "--stage";
  }
  if (options.target) {
    given.target = options.target;
    given.target_from = "--target";
  }
  given.harness = options.harness;
  given.pass = job.pass;
  given.channels = options.channels;
  if (job.channels) {
    for (size_t i = 0; i < given.channels.size(); ++i) given.channels[i] = (*job.channels)[i];
  }
  if (job.channels) given.channels_from = "the project's inputs";
  return given;
}

void RecordDecision(const FileDecision& decision, FileReport& report) {
  report.dialect = std::string(DialectName(decision.kind.dialect));
  report.stage = std::string(StageName(decision.kind.stage));
  report.harness = decision.harness != nullptr ? decision.harness->name : "";
  report.target = std::string(TargetName(decision.target));
  report.channels.clear();
  if (!decision.IsShaderToy()) return;
  for (const model::ChannelKind channel : decision.channels) {
    if (!report.channels.empty()) report.channels += ' ';
    report.channels += model::ChannelKindName(channel);
  }
}

FrontEndOptions FrontEndOptionsFor(const FileDecision& decision) {
  FrontEndOptions front_options;
  front_options.analyze = true;
  front_options.channels = decision.channels;
  // WebGL 2 contexts allow 1024-character names in GLSL ES 1.00 code too.
  front_options.max_identifier_length = decision.target == model::Target::kWebGL2 ? 1024 : 256;
  front_options.harness_header = decision.harness_header;
  front_options.harness_version = decision.harness_version;
  return front_options;
}

// The file's decision and the front end's result for what it decided. The tree
// completes the decision (a harness, cube-map channels); when that changes what the
// code sees, the front end runs again on the same tokens. Not when a limit was hit.
struct DecidedFile {
  FileDecision decision;
  FrontEndResult front;
  bool limit_breached = false;
};

DecidedFile DecideAndAnalyze(const SourceFile& file, glsl::LexedFile lexed, const FileJob& job,
                             const CheckOptions& options, SourceManager& sources) {
  const DecisionGiven given = GivenFor(job, options);
  DecidedFile result;
  FileDecision& decision = result.decision;
  decision = DecideFromTokens(lexed, job.path, given);
  const SourceFile* common = decision.IsShaderToy() ? job.common : nullptr;
  result.front = RunFrontEnd(file, std::move(lexed), common, decision.kind, sources,
                             FrontEndOptionsFor(decision));
  FrontEndResult& front = result.front;
  result.limit_breached = HasLimitBreach(front.diagnostics);
  if (!result.limit_breached && front.model &&
      DecideFromTree(decision, front.lexed, front.parsed.tree, *front.model, given)) {
    glsl::LexedFile tokens = std::move(front.lexed);
    front = RunFrontEnd(file, std::move(tokens), common, decision.kind, sources,
                        FrontEndOptionsFor(decision));
  }
  return result;
}

// Suppression comments, then the project's rule levels, then the per-file cap.
void Finalize(const FileJob& job, const SourceFile& file, const FrontEndResult& front,
              DiagnosticList& diagnostics) {
  ApplySuppressions(file, front.lexed, diagnostics, front.preprocessed.inactive_regions);
  if (job.config != nullptr) ApplyRuleConfig(*job.config, diagnostics);
  if (diagnostics.size() > limits::kMaxDiagnosticsPerFile) {
    diagnostics.resize(limits::kMaxDiagnosticsPerFile);
    diagnostics.back().notes.push_back({{},
                                        "further diagnostics in this file were not shown (limit " +
                                            std::to_string(limits::kMaxDiagnosticsPerFile) + ")"});
  }
}

RenderFileOptions RenderOptionsFor(const CheckOptions& options) {
  RenderFileOptions render_options;
  render_options.base.width = static_cast<uint32_t>(options.render_size);
  render_options.base.height = static_cast<uint32_t>(options.render_size);
  render_options.render.timeout =
      std::chrono::milliseconds(static_cast<int64_t>(options.render_timeout * 1000));
  return render_options;
}

// Smoke-renders a file that validated (WebGL1 code through its port).
void RenderChecked(const SourceFile& file, const FileDecision& decision, const SourceFile* common,
                   const CheckOptions& options, SourceManager& sources,
                   DiagnosticList& diagnostics) {
  RenderFileOptions render_options = RenderOptionsFor(options);
  render_options.channel_types = decision.channels;
  render_options.common = common;
  render_options.sources = &sources;
  render_options.harness = decision.harness;
  RenderFileResult rendered;
  RenderSource(file, decision.kind, render_options, rendered);
  for (Diagnostic& diagnostic : rendered.diagnostics) diagnostics.push_back(std::move(diagnostic));
}

}  // namespace

void RenderCheckedFile(const FileJob& job, const CheckOptions& options, SourceManager& sources,
                       FileReport& report, bool draw) {
  if (report.file == nullptr || report.file->Text().empty()) return;
  const SourceFile& file = *report.file;
  const DecidedFile decided = DecideAndAnalyze(file, glsl::Lex(file), job, options, sources);
  const FileDecision& decision = decided.decision;
  const FrontEndResult& front = decided.front;
  const SourceFile* common = decision.IsShaderToy() ? job.common : nullptr;
  // Drawn only when what remains after suppressions and configuration has no error.
  DiagnosticList settled = report.diagnostics;
  SuppressionOptions quiet;
  quiet.report_unused = false;
  ApplySuppressions(file, front.lexed, settled, front.preprocessed.inactive_regions, quiet);
  if (job.config != nullptr) ApplyRuleConfig(*job.config, settled);
  if (draw && !HasErrors(settled))
    RenderChecked(file, decision, common, options, sources, report.diagnostics);
  Finalize(job, file, front, report.diagnostics);
}

void RenderCheckedProject(const FileJob& image_job, const CheckOptions& options,
                          SourceManager& sources, FileReport& image_report) {
  const RenderFileOptions render_options = RenderOptionsFor(options);
  RenderFileResult rendered;
  if (const project::ShaderToyProject* whole = image_job.shadertoy_project) {
    // Passes are named as the check named them: "toy.json#Image" (the tab's file name).
    std::string name = image_job.path.string();
    const project::ProjectPass* image = whole->Find(model::PassKind::kImage);
    if (image != nullptr && name.ends_with("#" + image->name)) {
      name.resize(name.size() - image->name.size() - 1);
    }
    rendered = RenderShaderToyJson(name, project::ToRecordJson(*whole), sources, render_options);
  } else {
    rendered = RenderProject(image_job.project, sources, render_options);
    // A folder's Image tab is its own file: findings in the drawn copy of its code
    // point at that file, as the check's do.
    for (Diagnostic& diagnostic : rendered.diagnostics) {
      if (diagnostic.range.file == kNoFile || image_report.file == nullptr) continue;
      const SourceFile& drawn = sources.Get(diagnostic.range.file);
      if (drawn.Name() == image_job.project + "#Image" &&
          drawn.Text() == image_report.file->Text()) {
        diagnostic.range.file = image_report.file->Id();
      }
    }
  }
  if (image_job.config != nullptr) ApplyRuleConfig(*image_job.config, rendered.diagnostics);
  for (Diagnostic& diagnostic : rendered.diagnostics) {
    image_report.diagnostics.push_back(std::move(diagnostic));
  }
}

const SourceFile* LoadSharedFile(const std::filesystem::path& path, SourceManager& sources,
                                 std::string& error) {
  InputText input = ReadInputFile(path);
  if (!input.text) {
    error = path.string() + ": " + input.message;
    return nullptr;
  }
  return &sources.Add(path.string(), std::move(*input.text));
}

FileReport CheckFile(const FileJob& job, const CheckOptions& options, SourceManager& sources) {
  FileReport report;
  InputText input;
  if (job.source == nullptr)
    input = job.contents != nullptr ? *job.contents : ReadInputFile(job.path);
  if (job.source == nullptr && !input.text) {
    report.file = &sources.Add(job.path.string(), "");
    report.diagnostics.push_back(MakeDiagnostic(Severity::kError, std::move(input.rule_id),
                                                {report.file->Id(), 0, 0},
                                                std::move(input.message)));
    return report;
  }
  const SourceFile& file =
      job.source != nullptr ? *job.source : sources.Add(job.path.string(), std::move(*input.text));
  report.file = &file;
  // Lexed once: the decision, the front end, suppressions and glslang's messages share it.
  glsl::LexedFile lexed = glsl::Lex(file);
  DecidedFile decided = DecideAndAnalyze(file, std::move(lexed), job, options, sources);
  const FileDecision& decision = decided.decision;
  const FrontEndResult& front = decided.front;
  const SourceFile* common = decision.IsShaderToy() ? job.common : nullptr;
  RecordDecision(decision, report);
  if (options.explain_only) {
    report.decision = decision.reasons;
    return report;
  }
  // Our own front end ran first: it enforces the limits (glslang has none against,
  // e.g., 100,000 nested parentheses); a file that hit one is not given to glslang.
  if (decided.limit_breached) {
    report.diagnostics = LimitBreaches(front.diagnostics);
    return report;
  }
  WebglCheckSettings webgl;
  webgl.stage = decision.kind.stage;
  webgl.shadertoy = decision.IsShaderToy();
  webgl.target = decision.target;
  webgl.extensions = options.enabled_extensions;
  webgl.forced_version = decision.ForcedVersion();
  webgl.behind_header = decision.IsShaderToy();
  validate::ValidationRequest request = ComposeForGlslang(decision, file, common, sources);
  const rules::GlslangText glslang_text = TextForGlslang(file, common, file, front, webgl);
  const rules::GlslangText common_text = common != nullptr
                                             ? TextForGlslang(file, common, *common, front, webgl)
                                             : rules::GlslangText{};
  std::vector<validate::ShaderPart> parts;
  for (validate::ShaderPart& part : request.parts) {
    const rules::GlslangText* text = nullptr;
    if (part.kind == validate::PartKind::kUser && part.file == file.Id()) {
      part.source = &file;
      part.lexed = &front.lexed;
      text = &glslang_text;
    } else if (part.kind == validate::PartKind::kUser && common != nullptr &&
               part.file == common->Id()) {
      text = &common_text;
    }
    if (text != nullptr && !text->prelude.empty()) {
      const SourceFile& prelude = sources.Add("<glslang-prelude>", text->prelude, true);
      parts.push_back(
          {"glslang-prelude", prelude.Text(), prelude.Id(), validate::PartKind::kGenerated});
    }
    if (text != nullptr && !text->text.empty()) part.text = text->text;
    parts.push_back(part);
  }
  request.parts = std::move(parts);
  validate::ValidationResult result = validate::ValidateWithGlslang(request);
  // glslang crashed on the file's macros (or its child process failed: a differential
  // run of 20,000 files saw one such file crash in a batch and compile alone), which our
  // own preprocessor took: glslang compiles our expansion, in this process, so that its
  // checks still run. Not behind a Common part, whose macros the expansion would take out
  // of place. Only then: the expansion leaves out the rest of glslang's text
  // (TextForGlslang), so on a file glslang did compile it would raise false errors.
  std::string expanded;
  if (result.crashed && common == nullptr && !front.HasErrors()) {
    expanded = ExpandedTextForGlslang(file, file, front, webgl);
    validate::ValidationRequest again = request;
    again.texts_expanded = true;  // no macros left: glslang runs in this process
    for (validate::ShaderPart& part : again.parts) {
      if (part.kind == validate::PartKind::kUser && part.file == file.Id()) part.text = expanded;
    }
    validate::ValidationResult retried = validate::ValidateWithGlslang(again);
    if (!retried.crashed) {
      for (Diagnostic& diagnostic : retried.diagnostics) {
        diagnostic.notes.push_back(
            {{},
             "glslang crashed on this file's macros; this is glslang's message for "
             "shaderport's expansion of them"});
      }
      result = std::move(retried);
    }
  }
  AlignGlslangWithBrowser(file, front, webgl, result.diagnostics);
  ExplainChannelErrors(front, decision, result.diagnostics);
  report.diagnostics = RunWebglChecks(file, front, webgl);
  for (Diagnostic& diagnostic : result.diagnostics)
    report.diagnostics.push_back(std::move(diagnostic));
  if (common != nullptr && job.common_checked_separately) {
    // Common is an input of its own: its findings are reported once, there. The site
    // compiles the Common tab without a pass's wrapper, so what a macro of Common does
    // to that wrapper only the passes can tell.
    std::erase_if(report.diagnostics, [&](const Diagnostic& d) {
      return d.range.file == common->Id() && d.rule_id != "shadertoy/macro-rewrites-wrapper";
    });
  }
  // What `shaderport fix` would repair, so that every format can say so.
  if (AnyFindingWithoutFix(report.diagnostics) && FixOffersAnEdit(file, front, decision)) {
    AttachRepairs(PortSource(file, common, FixOptionsFor(decision), sources), sources,
                  report.diagnostics);
  }
  // With --render the picture's findings join later (RenderCheckedFile), and
  // suppressions and configuration are applied to all of them together there.
  if (!options.render) Finalize(job, file, front, report.diagnostics);
  return report;
}

}  // namespace shaderport::driver
