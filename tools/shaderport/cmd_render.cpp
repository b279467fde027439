// `shaderport render PATH -o OUT.png`: draws one shader headless and checks the picture.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "base/file_io/atomic_write.h"
#include "base/file_io/writable_path.h"
#include "base/printable.h"
#include "cli_errors.h"
#include "commands.h"
#include "driver/check_file.h"
#include "driver/input_files.h"
#include "driver/port/output_files.h"
#include "driver/render_check/render_multipass.h"
#include "option_names.h"
#include "port_arguments.h"
#include "render/png_io.h"
#include "report/output_format.h"

namespace shaderport::cli {
namespace {

struct RenderArgs {
  std::string path;
  std::string output;
  std::string size = "64x64";
  int frames = 1;
  float time = 1.0f;
  int frame = 0;
  std::vector<float> mouse;
  std::array<std::string, 4> channels;
  std::vector<std::string> channel_types;
  std::string common;
  std::string backend;
  double timeout_seconds = 10.0;
  bool hermetic = false;
  bool native = false;
  bool browser_optimiser = false;
  std::string fail_on = "error";
};

// One side of --size: 1 to 4 decimal digits (sscanf's %u would take "-1" as 4294967295
// and wrap, so the digits are read by hand).
std::optional<uint32_t> ParseSide(std::string_view text) {
  if (text.empty() || text.size() > 4) return std::nullopt;
  uint32_t side = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    side = side * 10 + static_cast<uint32_t>(c - '0');
  }
  if (side == 0 || side > render::kMaxRenderSide) return std::nullopt;
  return side;
}

bool ParseSize(std::string_view text, uint32_t& width, uint32_t& height) {
  const size_t x = text.find('x');
  if (x == std::string_view::npos) return false;
  const std::optional<uint32_t> w = ParseSide(text.substr(0, x));
  const std::optional<uint32_t> h = ParseSide(text.substr(x + 1));
  if (!w || !h) return false;
  width = *w;
  height = *h;
  return true;
}

int RunRender(const RenderArgs& args) {
  driver::RenderFileOptions options;
  if (!ParseSize(args.size, options.base.width, options.base.height)) {
    return UsageError("--size must be WIDTHxHEIGHT, each 1..4096");
  }
  if (args.frames < 1 || args.frames > 10000) return UsageError("--frames must be 1..10000");
  if (!args.mouse.empty() && args.mouse.size() != 2 && args.mouse.size() != 4) {
    return UsageError("--mouse takes x,y or x,y,click_x,click_y");
  }
  // NaN fails every comparison: without isfinite it would pass this test.
  if (!std::isfinite(args.timeout_seconds) || args.timeout_seconds <= 0 ||
      args.timeout_seconds > 3600) {
    return UsageError("--timeout must be more than 0 and at most 3600 seconds");
  }
  if (!std::isfinite(args.time)) return UsageError("--time must be a finite number of seconds");
  if (args.frame < 0) return UsageError("--frame must be 0 or more");
  if (!std::all_of(args.mouse.begin(), args.mouse.end(),
                   [](float v) { return std::isfinite(v); })) {
    return UsageError("--mouse coordinates must be finite numbers");
  }
  if (!args.backend.empty()) {
    const auto backend = render::BackendFromName(args.backend);
    if (!backend) return UsageError(UnknownName("--backend", args.backend, kBackendNames));
    options.render.backend = *backend;
  }
  for (const std::string& spec : args.channel_types) {
    const std::optional<ChannelSpec> parsed = ParseChannelSpec(spec);
    if (!parsed) return UsageError("--channel-type takes N=2d|cube|3d");
    options.channel_types_given[parsed->index] = true;
    options.channel_types[parsed->index] = parsed->kind;
  }
  options.base.frames = args.frames;
  options.base.inputs.time = args.time;
  options.base.inputs.frame = args.frame;
  for (size_t i = 0; i < args.mouse.size(); ++i) options.base.inputs.mouse[i] = args.mouse[i];
  options.channel_images = args.channels;
  options.render.timeout =
      std::chrono::milliseconds(static_cast<int64_t>(args.timeout_seconds * 1000));
  options.render.hermetic = args.hermetic;
  options.webgl_semantics = !args.native;
  options.browser_optimiser = args.browser_optimiser;
  if (args.native && args.browser_optimiser) {
    return UsageError("--browser-optimiser needs the browser semantics that --native turns off");
  }
  const std::optional<Severity> fail_on = SeverityFromName(args.fail_on);
  if (!fail_on) return UsageError(UnknownName("--fail-on", args.fail_on, kSeverityNames));

  if (const std::string missing = driver::MissingPathError(args.path); !missing.empty()) {
    return UsageError(missing);
  }
  if (!args.output.empty()) {
    // Before drawing: "rendered" must never be printed for a picture that cannot be kept.
    if (const std::string why = file_io::UnwritablePath(args.output); !why.empty()) {
      return UsageError(why);
    }
    std::vector<std::filesystem::path> read{args.path, args.common};
    read.insert(read.end(), args.channels.begin(), args.channels.end());
    if (const std::string clash = driver::OutputReplacesInput("-o", args.output, read);
        !clash.empty()) {
      return UsageError(clash);
    }
  }
  SourceManager sources;
  if (!args.common.empty()) {
    std::string error;
    options.common = driver::LoadSharedFile(args.common, sources, error);
    if (options.common == nullptr) return UsageError(error);
  }
  driver::RenderFileResult result = driver::RenderInput(args.path, sources, options);
  int code = kExitOk;
  if (result.image && !args.output.empty()) {
    const std::string png = render::EncodePng(*result.image);
    const std::string error = png.empty() ? "cannot encode the picture as PNG"
                                          : file_io::WriteFileAtomically(args.output, png);
    if (!error.empty()) {
      PrintError(error);
      code = kExitInternal;
    }
  }
  if (!result.diagnostics.empty()) {
    CheckReport report;
    report.sources = &sources;
    FileReport file;
    file.file = result.file;
    file.dialect = result.dialect;
    file.stage = result.stage;
    file.diagnostics = std::move(result.diagnostics);
    report.files.push_back(std::move(file));
    SortReport(report);
    ReportOptions report_options;
    report_options.tool_version = SHADERPORT_VERSION;
    const std::string text = FormatReport(report, OutputFormat::kText, report_options);
    std::fwrite(text.data(), 1, text.size(), stderr);
    const bool fails = std::any_of(report.files.front().diagnostics.begin(),
                                   report.files.front().diagnostics.end(),
                                   [&](const Diagnostic& d) { return d.severity >= *fail_on; });
    if (fails && code == kExitOk) code = kExitFindings;
  }
  if (result.image) {
    std::printf("%s: rendered %ux%u in %.0f ms%s%s\n", EscapeControlCharacters(args.path).c_str(),
                result.image->width, result.image->height, result.milliseconds,
                args.output.empty() ? "" : " -> ", EscapeControlCharacters(args.output).c_str());
  }
  return code;
}

}  // namespace

void AddRenderCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<RenderArgs>();
  auto* command = app.add_subcommand(
      "render", "Draw a shader headless (OSMesa/EGL), check the picture and write a PNG");
  command
      ->add_option("file", args->path,
                   "ShaderToy pass, WebGL2 shader, or ShaderToy JSON export (multipass)")
      ->required();
  command->add_option("-o,--output", args->output, "PNG file for the final frame");
  command->add_option("--size", args->size, "Picture size WIDTHxHEIGHT (default 64x64)");
  command->add_option("--frames", args->frames, "Frames to draw; the last is kept (default 1)");
  command->add_option("--time", args->time, "iTime of the first frame in seconds (default 1)");
  command->add_option("--frame", args->frame, "iFrame of the first frame (default 0)");
  command->add_option("--mouse", args->mouse, "iMouse: x,y[,click_x,click_y] in pixels")
      ->delimiter(',')
      ->allow_extra_args(false);
  for (size_t i = 0; i < 4; ++i) {
    command->add_option("--channel" + std::to_string(i), args->channels[i],
                        "PNG image for iChannel" + std::to_string(i));
  }
  command
      ->add_option("--channel-type", args->channel_types,
                   "Sampler kind of a ShaderToy channel: N=2d|cube|3d (repeatable)")
      ->allow_extra_args(false);
  command->add_option("--common", args->common, "ShaderToy Common code to prepend");
  command->add_option("--backend", args->backend, "osmesa or egl (default osmesa)");
  command->add_option("--timeout", args->timeout_seconds,
                      "Seconds before the render is killed (default 10)");
  command->add_flag("--hermetic", args->hermetic, "Do not use or fill Mesa's shader cache");
  command->add_flag("--native", args->native,
                    "Draw as a native driver would: without the browser's zero initialisation, "
                    "index clamping and math");
  command->add_flag("--browser-optimiser", args->browser_optimiser,
                    "Also run spirv-opt -O on the text, as Chromium's SwiftShader does, for its "
                    "regroupings of float arithmetic (slower)");
  command->add_option("--fail-on", args->fail_on,
                      "Lowest severity that fails the run: error (default), warning or note");
  command->callback([args, &exit_code] { exit_code = RunRender(*args); });
}

}  // namespace shaderport::cli
