#include "driver/render_check/render_file.h"

#include "diag/limit_breach.h"
#include "driver/dialect.h"
#include "driver/file_decision.h"
#include "driver/front_end.h"
#include "driver/port/port_file.h"
#include "driver/read_input.h"
#include "driver/render_check/browser_optimizer.h"
#include "driver/render_check/browser_render_text.h"
#include "driver/render_check/composed_text.h"
#include "driver/render_check/varying_feeder.h"
#include "glsl/webgl_semantics/browser_semantics.h"
#include "render/isolated_render.h"
#include "render/loop_cap.h"
#include "render/png_io.h"

namespace shaderport::driver {
namespace {

// On request, Mesa draws the text after the optimiser Chromium runs
// (browser_optimizer.h); when that text cannot be made or Mesa rejects it, the text as
// the browser semantics wrote it, whose diagnostics point at the user's lines.
render::RenderOutcome RenderAsBrowser(const render::RenderRequest& request,
                                      const RenderFileOptions& options) {
  if (options.webgl_semantics && options.browser_optimiser) {
    render::RenderRequest optimized = request;
    bool complete = true;
    for (render::BufferPass& pass : optimized.buffer_passes) {
      auto text = OptimizeAsBrowser(pass.fragment_source);
      if (!text) {
        complete = false;  // one pass without the optimiser: none gets it
        break;
      }
      pass.fragment_source = std::move(*text);
    }
    auto text = complete ? OptimizeAsBrowser(request.fragment_source) : std::nullopt;
    if (text) {
      optimized.fragment_source = std::move(*text);
      render::RenderOutcome outcome = render::RenderIsolated(optimized, options.render);
      if (outcome.status != render::RenderStatus::kCompileFailed &&
          outcome.status != render::RenderStatus::kLinkFailed) {
        return outcome;
      }
    }
  }
  return render::RenderIsolated(request, options.render);
}

}  // namespace

void RenderPrepared(const PreparedShader& shader, const RenderFileOptions& options,
                    RenderFileResult& result) {
  render::RenderRequest request = options.base;
  // Mesa compiles what a browser would hand its driver (zero-initialised variables,
  // clamped indices), with a probe that tells when llvmpipe's loop cap was hit.
  BrowserRenderTextOptions semantics;
  semantics.webgl_semantics = options.webgl_semantics;
  semantics.cpu_browser_math = true;
  semantics.opaque_helper_arguments = options.browser_optimiser;
  for (render::BufferPass& pass : request.buffer_passes) {
    pass.fragment_source = BrowserRenderText(pass.fragment_source, semantics);
  }
  semantics.vertex_stage = true;
  request.vertex_source = shader.fullscreen_vertex
                              ? shader.vertex_text
                              : BrowserRenderText(shader.vertex_text, semantics);
  semantics.vertex_stage = false;
  semantics.add_render_probe = true;
  // Not through the SPIR-V optimiser: it drops the probe variable's stores of branch
  // conditions as dead (an output's stores it keeps), and with them their exactness.
  semantics.probe_in_alpha = shader.main_sets_alpha && !options.browser_optimiser;
  request.fullscreen_vertex = shader.fullscreen_vertex;
  ProbedRenderText fragment = BrowserRenderTextWithProbe(shader.fragment_text, semantics);
  request.fragment_source = std::move(fragment.text);
  // The probe is an output at location 1, or it rides in the colour's alpha.
  request.probe_in_alpha = fragment.probe_in_alpha;
  if (!request.probe_in_alpha) request.probe_output = std::string(glsl::kRenderProbeOutput);
  for (size_t i = 0; i < 4; ++i) {
    request.inputs.channels[i].kind = options.channel_types[i];
    if (options.channel_images[i].empty()) continue;
    std::string error;
    if (!render::ReadPng(options.channel_images[i], request.inputs.channels[i].image, error)) {
      result.diagnostics.push_back(
          MakeDiagnostic(Severity::kError, "render/channel-image", shader.anchor, error));
      return;
    }
  }
  const render::RenderOutcome outcome = RenderAsBrowser(request, options);
  result.milliseconds = outcome.milliseconds;
  render::CheckContext context;
  context.anchor = shader.anchor;
  context.map_line = shader.map_line;
  context.map_buffer_line = shader.map_buffer_line;
  context.expect_full_coverage = !shader.fragment_text.empty();
  context.fragment_text = shader.fragment_text;
  DiagnosticList found = render::CheckOutcome(outcome, context);
  result.diagnostics.insert(result.diagnostics.end(), found.begin(), found.end());
  if (outcome.status == render::RenderStatus::kOk) {
    result.image = render::ToImage(outcome);
    if (shader.user != nullptr) {
      DiagnosticList notes = render::LoopCapFindings(*shader.user, outcome, shader.anchor);
      result.diagnostics.insert(result.diagnostics.end(), notes.begin(), notes.end());
    }
  }
}

RenderFileResult RenderFile(const std::filesystem::path& path, SourceManager& sources,
                            const RenderFileOptions& options) {
  RenderFileResult result;
  InputText input = ReadInputFile(path);
  if (!input.text) {
    const SourceFile& empty = sources.Add(path.string(), "");
    result.file = &empty;
    result.diagnostics.push_back(
        MakeDiagnostic(Severity::kError, input.rule_id, empty.WholeRange(), input.message));
    return result;
  }
  const SourceFile& file = sources.Add(path.string(), std::move(*input.text));
  DecisionGiven given;
  given.harness = options.harness;
  for (size_t i = 0; i < given.channels.size(); ++i) {
    if (options.channel_types_given[i]) given.channels[i] = options.channel_types[i];
  }
  given.channels_from = "--channel-type";
  const FileDecision decision = DecideFile(file, options.common, given, sources);
  RenderFileOptions with_sources = options;
  with_sources.sources = &sources;
  with_sources.channel_types = decision.channels;
  with_sources.harness = decision.harness;
  RenderSource(file, decision.kind, with_sources, result);
  return result;
}

DiagnosticList RenderLimitBreaches(const SourceFile& file, const DetectedKind& kind,
                                   const SourceFile* common, SourceManager& sources) {
  const bool shadertoy = kind.dialect == Dialect::kShaderToy;
  return LimitBreaches(RunFrontEnd(file, shadertoy ? common : nullptr, kind, sources).diagnostics);
}

void RenderSource(const SourceFile& file, const DetectedKind& kind,
                  const RenderFileOptions& options, RenderFileResult& result) {
  result.file = &file;
  result.dialect = std::string(DialectName(kind.dialect));
  result.stage = std::string(StageName(kind.stage));
  const SourceRange anchor{file.Id(), 0, 0};
  SourceManager own_sources;
  result.diagnostics = RenderLimitBreaches(
      file, kind, options.common, options.sources != nullptr ? *options.sources : own_sources);
  if (!result.diagnostics.empty()) return;

  PreparedShader shader;
  shader.anchor = anchor;
  shader.user = &file;
  if (kind.dialect == Dialect::kShaderToy) {
    const model::PassKind pass = kind.pass;
    if (pass == model::PassKind::kCommon) {
      result.diagnostics.push_back(
          MakeDiagnostic(Severity::kNote, "render/not-rendered", anchor,
                         "a Common file is rendered with the passes using it"));
      return;
    }
    auto composed = std::make_shared<ComposedText>();
    composed->Append(validate::ShaderToyHeader(pass, options.channel_types), nullptr);
    if (options.common != nullptr) composed->Append(options.common->Text(), options.common);
    composed->Append(file.Text(), &file);
    composed->Append(validate::ShaderToyEpilogue(pass), nullptr);
    shader.fragment_text = composed->Text();
    shader.main_sets_alpha = pass == model::PassKind::kImage;
    shader.map_line = [composed](model::Stage, uint32_t line) { return composed->MapLine(line); };
  } else if (kind.dialect == Dialect::kWebGL2) {
    auto composed = std::make_shared<ComposedText>();
    composed->Append(file.Text(), &file);
    (kind.stage == model::Stage::kVertex ? shader.vertex_text : shader.fragment_text) =
        composed->Text();
    // A fragment shader with inputs gets a vertex shader that writes them.
    if (kind.stage == model::Stage::kFragment) {
      shader.vertex_text = FeederVertexShader(file.Text());
      shader.fullscreen_vertex = true;
    }
    shader.map_line = [composed](model::Stage, uint32_t line) { return composed->MapLine(line); };
  } else {
    // WebGL1 code is drawn as `port` turns it into WebGL2; findings in the
    // ported text point into a synthetic "<file> (ported)" file, as that is
    // the text that was drawn.
    if (options.sources == nullptr) {
      result.diagnostics.push_back(
          MakeDiagnostic(Severity::kNote, "render/not-rendered", anchor,
                         "WebGL1 code is rendered after `shaderport port`"));
      return;
    }
    PortOptions port_options;
    port_options.dialect = Dialect::kWebGL1;
    port_options.stage = kind.stage;
    port_options.harness = options.harness;
    const PortResult ported = PortSource(file, nullptr, port_options, *options.sources);
    if (!ported.validated) {
      result.diagnostics.push_back(
          MakeDiagnostic(Severity::kNote, "render/not-rendered", anchor,
                         "not rendered: the WebGL2 port of this file does not "
                         "validate (see `shaderport port`)"));
      return;
    }
    const SourceFile& text =
        options.sources->Add(file.Name() + " (ported)", ported.text, /*synthetic=*/true);
    DetectedKind webgl2 = kind;
    webgl2.dialect = Dialect::kWebGL2;
    RenderSource(text, webgl2, options, result);
    result.file = &file;
    result.dialect = std::string(DialectName(kind.dialect));
    return;
  }
  RenderPrepared(shader, options, result);
}

}  // namespace shaderport::driver
