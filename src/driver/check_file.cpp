#include "driver/check_file.h"

#include <chrono>
#include <string_view>
#include <utility>

#include "base/limits.h"
#include "diag/limit_breach.h"
#include "driver/dialect.h"
#include "driver/front_end.h"
#include "driver/read_input.h"
#include "driver/render_check/render_file.h"
#include "driver/suppress/suppressions.h"
#include "driver/validate_kinds.h"
#include "driver/webgl_checks.h"
#include "validate/glslang_validator.h"
#include "validate/shadertoy_contract.h"

namespace shaderport::driver {
namespace {

DetectedKind ResolveKind(const FileJob& job, const CheckOptions& options,
                         const glsl::LexedFile& lexed) {
  DetectedKind kind = DetectKind(lexed, job.path);
  if (job.config != nullptr) {
    const FileSettings settings = SettingsFor(*job.config, job.absolute_path);
    if (settings.dialect) kind.dialect = *settings.dialect;
    if (settings.stage) kind.stage = *settings.stage;
  }
  if (options.dialect) kind.dialect = *options.dialect;
  if (options.stage) kind.stage = *options.stage;
  if (job.pass) {
    kind.dialect = Dialect::kShaderToy;
    kind.stage = Stage::kFragment;
    kind.pass = *job.pass;
  }
  return kind;
}

const validate::ChannelTypes& ChannelsOf(const FileJob& job, const CheckOptions& options) {
  return job.channels ? *job.channels : options.channels;
}

// --target, then the config's [[files]] target, then the default for the code.
Target ResolveTarget(const FileJob& job, const CheckOptions& options, const DetectedKind& kind,
                     const glsl::LexedFile& lexed) {
  if (options.target) return *options.target;
  if (job.config != nullptr) {
    const FileSettings settings = SettingsFor(*job.config, job.absolute_path);
    if (settings.target) return *settings.target;
  }
  if (kind.dialect == Dialect::kShaderToy) return Target::kWebGL2;
  // By the code's own #version, whatever --dialect says about how it is written.
  const Dialect written = DetectKind(lexed, job.path).dialect;
  return written == Dialect::kWebGL1 ? Target::kWebGL1 : Target::kWebGL2;
}

validate::ValidationRequest ComposeRequest(const FileJob& job, const CheckOptions& options,
                                           const DetectedKind& kind, const SourceFile& file,
                                           SourceManager& sources) {
  const validate::Stage stage = ToValidateStage(kind.stage);
  if (kind.dialect != Dialect::kShaderToy) {
    validate::ValidationRequest request;
    request.parts.push_back({file.Name(), file.Text(), file.Id(), validate::PartKind::kUser});
    request.stage = stage;
    request.default_version = 100;  // no #version means GLSL ES 1.00, as in WebGL
    return request;
  }
  const bool is_common = kind.pass == ShaderToyPass::kCommon;
  validate::ValidationRequest request =
      validate::ComposeShaderToyRequest(sources, ToPassType(kind.pass), ChannelsOf(job, options),
                                        is_common ? nullptr : job.common, file);
  // Common code has no entry point of its own: the site only compiles it inside
  // a pass, so here it is compiled but not linked.
  if (is_common) request.link = false;
  return request;
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

// Smoke-renders a file that validated (WebGL1 code through its port).
void RenderChecked(const SourceFile& file, const DetectedKind& kind, const SourceFile* common,
                   const validate::ChannelTypes& channels, const CheckOptions& options,
                   SourceManager& sources, DiagnosticList& diagnostics) {
  RenderFileOptions render_options;
  render_options.base.width = static_cast<uint32_t>(options.render_size);
  render_options.base.height = static_cast<uint32_t>(options.render_size);
  render_options.render.timeout =
      std::chrono::milliseconds(static_cast<int64_t>(options.render_timeout * 1000));
  render_options.channel_types = channels;
  render_options.common = common;
  render_options.sources = &sources;
  RenderFileResult rendered;
  RenderSource(file, kind, render_options, rendered);
  for (Diagnostic& diagnostic : rendered.diagnostics) diagnostics.push_back(std::move(diagnostic));
}

}  // namespace

void RenderCheckedFile(const FileJob& job, const CheckOptions& options, SourceManager& sources,
                       FileReport& report) {
  if (report.file == nullptr || report.file->Text().empty()) return;
  const SourceFile& file = *report.file;
  glsl::LexedFile lexed = glsl::Lex(file);
  const DetectedKind kind = ResolveKind(job, options, lexed);
  const SourceFile* common = kind.dialect == Dialect::kShaderToy ? job.common : nullptr;
  const FrontEndResult front = RunFrontEnd(file, std::move(lexed), common, kind, sources);
  // Drawn only when what remains after suppressions and configuration has no error.
  DiagnosticList settled = report.diagnostics;
  SuppressionOptions quiet;
  quiet.report_unused = false;
  ApplySuppressions(file, front.lexed, settled, front.preprocessed.inactive_regions, quiet);
  if (job.config != nullptr) ApplyRuleConfig(*job.config, settled);
  if (!HasErrors(settled))
    RenderChecked(file, kind, common, ChannelsOf(job, options), options, sources,
                  report.diagnostics);
  Finalize(job, file, front, report.diagnostics);
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
  // Lexed once: detection, the front end, suppressions and glslang's messages share it.
  glsl::LexedFile lexed = glsl::Lex(file);
  const DetectedKind kind = ResolveKind(job, options, lexed);
  report.dialect = std::string(DialectName(kind.dialect));
  report.stage = std::string(StageName(kind.stage));

  const SourceFile* common = kind.dialect == Dialect::kShaderToy ? job.common : nullptr;
  // Our own front end runs first: it enforces the limits (glslang has none
  // against, e.g., 100,000 nested parentheses), its tokens give the suppression
  // comments and inactive regions, and its tree feeds the WebGL rules.
  WebglCheckSettings webgl;
  webgl.stage = kind.stage;
  webgl.shadertoy = kind.dialect == Dialect::kShaderToy;
  webgl.target = ResolveTarget(job, options, kind, lexed);
  FrontEndOptions front_options;
  front_options.analyze = true;
  front_options.channels = ChannelsOf(job, options);
  // WebGL 2 contexts allow 1024-character names in GLSL ES 1.00 code too.
  front_options.max_identifier_length = webgl.target == Target::kWebGL2 ? 1024 : 256;
  const FrontEndResult front =
      RunFrontEnd(file, std::move(lexed), common, kind, sources, front_options);
  // Past a limit only the breach is reported: glslang is not run on such text.
  report.diagnostics = LimitBreaches(front.diagnostics);
  if (!report.diagnostics.empty()) return report;

  validate::ValidationRequest request = ComposeRequest(job, options, kind, file, sources);
  const std::string glslang_text = TextForGlslang(file, file, front, webgl);
  const std::string common_text =
      common != nullptr ? TextForGlslang(file, *common, front, webgl) : std::string();
  for (validate::ShaderPart& part : request.parts) {
    if (part.kind != validate::PartKind::kUser) continue;
    if (part.file == file.Id()) {
      part.source = &file;
      part.lexed = &front.lexed;
      if (!glslang_text.empty()) part.text = glslang_text;
    } else if (common != nullptr && part.file == common->Id() && !common_text.empty()) {
      part.text = common_text;
    }
  }
  validate::ValidationResult result = validate::ValidateWithGlslang(request);
  AlignGlslangWithBrowser(file, front, webgl, result.diagnostics);
  report.diagnostics = RunWebglChecks(file, front, webgl);
  for (Diagnostic& diagnostic : result.diagnostics)
    report.diagnostics.push_back(std::move(diagnostic));
  if (common != nullptr && job.common_checked_separately) {
    // Common is an input of its own: its findings are reported once, there.
    std::erase_if(report.diagnostics,
                  [&](const Diagnostic& d) { return d.range.file == common->Id(); });
  }
  // With --render the picture's findings join later (RenderCheckedFile), and
  // suppressions and configuration are applied to all of them together there.
  if (!options.render) Finalize(job, file, front, report.diagnostics);
  return report;
}

}  // namespace shaderport::driver
