#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "base/file_io/atomic_write.h"
#include "base/file_io/read_regular_file.h"
#include "base/limits.h"
#include "cache_settings.h"
#include "cli_errors.h"
#include "commands.h"
#include "driver/check_pipeline.h"
#include "driver/port/output_files.h"
#include "driver/port/rule_reference.h"
#include "driver/read_input.h"
#include "empty_input.h"
#include "model/webgl_extensions.h"
#include "option_names.h"
#include "port_arguments.h"
#include "progress_line.h"
#include "report/baseline.h"
#include "report/merge.h"
#include "report/output_format.h"
#include "report/statistics.h"
#include "report/text_format.h"

namespace shaderport::cli {
namespace {

// The longest --render-timeout, as for `render --timeout` (docs/limits.md).
constexpr double kMaxRenderTimeoutSeconds = 3600;

struct CheckArgs {
  std::vector<std::string> paths;
  std::string format = "text";
  std::string fail_on;
  std::string dialect;
  std::string stage;
  std::string target;
  std::optional<std::string> enabled_extensions;  // --enabled-extensions
  std::vector<std::string> link;
  std::string common;
  std::vector<std::string> channels;
  std::string config;
  bool no_config = false;
  bool no_force_exclude = false;  // --no-force-exclude
  bool allow_empty = false;       // --allow-empty
  unsigned jobs = 0;
  std::string color = "auto";
  bool render = false;
  int render_size = 64;
  double render_timeout = 10;
  bool stdin_input = false;    // --stdin
  std::string stdin_filename;  // --stdin-filename
  bool statistics = false;
  bool quiet = false;
  std::string progress = "auto";
  std::string cache_dir;  // --cache-dir
  bool no_cache = false;
  std::string shard;           // --shard K/N
  std::string baseline;        // --baseline FILE
  std::string write_baseline;  // --write-baseline FILE
};

std::optional<Baseline> ReadBaselineFile(const std::string& path, std::string& error) {
  file_io::ReadResult read = file_io::ReadRegularFile(path, limits::kMaxReportBytes);
  if (!read.bytes) {
    error = read.message;
    return std::nullopt;
  }
  return ParseBaseline(*read.bytes, error);
}

bool UseColor(const std::string& mode) {
  if (mode == "always") return true;
  if (mode == "never") return false;
  const char* no_color = std::getenv("NO_COLOR");
  return isatty(STDOUT_FILENO) != 0 && (no_color == nullptr || *no_color == '\0');
}

int RunCheckCommand(const CheckArgs& args) {
  driver::CheckOptions options;
  SourceManager dialect_sources;  // a --dialect FILE.toml, kept for its diagnostics
  std::optional<model::HarnessDialect> harness;
  for (const std::string& path : args.paths) options.paths.emplace_back(path);
  const auto format = ParseOutputFormat(args.format);
  if (!format) return UsageError(UnknownName("--format", args.format, kFormatNames));
  if (std::find(kWhenNames.begin(), kWhenNames.end(), args.color) == kWhenNames.end()) {
    return UsageError(UnknownName("--color", args.color, kWhenNames));
  }
  if (!ResolveKindOptions({args.dialect, args.stage, args.target}, dialect_sources, options,
                          harness)) {
    return kExitUsage;
  }
  if (args.enabled_extensions) {
    std::string error;
    const auto enabled = model::ParseEnabledExtensions(*args.enabled_extensions, error);
    if (!enabled) return UsageError(error);
    options.enabled_extensions = *enabled;
  }
  if (!args.link.empty()) {
    if (args.link.size() % 2 != 0) return UsageError("--link takes a vertex and a fragment shader");
    for (size_t i = 0; i + 1 < args.link.size(); i += 2) {
      options.links.emplace_back(args.link[i], args.link[i + 1]);
      options.paths.emplace_back(args.link[i]);
      options.paths.emplace_back(args.link[i + 1]);
    }
  }
  if (!args.fail_on.empty()) {
    options.fail_on = SeverityFromName(args.fail_on);
    if (!options.fail_on) return UsageError(UnknownName("--fail-on", args.fail_on, kSeverityNames));
  }
  for (const std::string& spec : args.channels) {
    if (!ParseChannel(spec, options.channels)) {
      return UsageError("bad --channel '" + spec + "' (expected N=2d|cube|3d, N from 0 to 3)");
    }
  }
  if (!args.common.empty()) options.common = args.common;
  if (!args.config.empty()) options.config = args.config;
  options.use_config = !args.no_config;
  options.force_exclude = !args.no_force_exclude;
  options.jobs = args.jobs;
  if (args.render_size < 1 || args.render_size > 4096) {
    return UsageError("--render-size must be between 1 and 4096");
  }
  // NaN fails every comparison: without isfinite it would pass this test.
  if (!std::isfinite(args.render_timeout) || args.render_timeout <= 0 ||
      args.render_timeout > kMaxRenderTimeoutSeconds) {
    return UsageError("--render-timeout must be more than 0 and at most 3600 seconds");
  }
  options.render = args.render;
  options.render_size = args.render_size;
  options.render_timeout = args.render_timeout;
  if (!args.shard.empty()) {
    std::string error;
    options.shard = driver::ParseShardSpec(args.shard, error);
    if (!options.shard) return UsageError(error);
  }
  if (!args.no_cache) {
    options.cache_directory = CacheDirectory(args.cache_dir);
    options.tool_identity = ToolIdentity();
  }
  if (!args.write_baseline.empty()) {
    const std::vector<std::filesystem::path> named(args.paths.begin(), args.paths.end());
    const std::string clash =
        driver::OutputReplacesInput("--write-baseline", args.write_baseline, named);
    if (!clash.empty()) return UsageError(clash);
  }
  std::optional<Baseline> baseline;
  if (!args.baseline.empty()) {
    std::string error;
    baseline = ReadBaselineFile(args.baseline, error);
    if (!baseline) return UsageError("bad --baseline '" + args.baseline + "': " + error);
  }

  const std::optional<ProgressMode> progress_mode = ParseProgressMode(args.progress);
  if (!progress_mode) return UsageError(UnknownName("--progress", args.progress, kWhenNames));
  if (!args.stdin_filename.empty() && !args.stdin_input) {
    return UsageError("--stdin-filename needs --stdin");
  }
  if (args.stdin_input) {
    if (!options.paths.empty()) return UsageError("--stdin takes no files, directories or --link");
    const std::string name = args.stdin_filename.empty() ? "<stdin>" : args.stdin_filename;
    options.in_memory = {name, driver::ReadInputStream(std::cin)};
  } else if (options.paths.empty()) {
    return UsageError("no files or directories to check");
  }
  // -q asks for the findings alone; --progress always still draws the line.
  ProgressLine progress(
      args.quiet && *progress_mode == ProgressMode::kAuto ? ProgressMode::kNever : *progress_mode,
      "checking");
  options.progress = [&progress](size_t done, size_t total) { progress.Update(done, total); };
  options.release_clean_texts = true;  // the formats below print findings only
  driver::CheckRun run = driver::RunCheck(options);
  progress.Clear();
  if (!args.allow_empty) {
    // An unexpanded glob or a directory without shaders is a mistake in CI: a
    // gate that checks nothing must not pass (eslint's errorOnUnmatchedPattern).
    run.usage_errors.insert(run.usage_errors.end(), run.unmatched.begin(), run.unmatched.end());
    if (run.found_nothing && run.usage_errors.empty() && !args.stdin_input) {
      return UsageError(NothingToDo(args.paths, "check"));
    }
  }
  for (const std::string& error : run.usage_errors) PrintError(error);
  if (!run.usage_errors.empty() && run.report.files.empty()) return kExitUsage;  // nothing ran
  SortReport(run.report);
  ReportOptions report_options;
  report_options.tool_version = SHADERPORT_VERSION;
  report_options.base_directory = std::filesystem::current_path().string();
  report_options.color = *format == OutputFormat::kText && UseColor(args.color);
  report_options.rules_with_sections = driver::PortingRuleIds();
  // Baselined findings are left out of every format and of the verdict.
  std::string baseline_notice;
  if (baseline) {
    const BaselineOutcome outcome =
        ApplyBaseline(run.report, *baseline, report_options.base_directory);
    run.failed = ReportFails(run.report);
    baseline_notice = FormatBaselineSummary(outcome);
  }
  const bool text = *format == OutputFormat::kText;
  // Text: findings, the statistics, then the summary line last, where tools look for it.
  report_options.summary_line = !args.quiet && !(text && args.statistics);
  std::string output = FormatReport(run.report, *format, report_options);
  // Shards say which they are (merge refuses a missing one); SARIF also says
  // which file each result belongs to, which merge needs to join them.
  if (options.shard && (*format == OutputFormat::kSarif || *format == OutputFormat::kJson)) {
    output = AddShardMarkers(
        output, *format == OutputFormat::kSarif ? MergeFormat::kSarif : MergeFormat::kJson,
        run.report, {options.shard->index, options.shard->count});
  }
  if (args.statistics) {
    const std::string table = FormatStatistics(CountByRule(run.report));
    if (!text) {
      std::fputs(table.c_str(), stderr);  // stdout stays machine-readable
    } else {
      if (!output.empty() && !table.empty()) output += '\n';
      output += table;
      if (!args.quiet) {
        const ReportSummary counts = Summarize(run.report);
        const std::string summary = SummaryLine(counts);
        output += report_options.color ? "\x1b[1m" + summary + "\x1b[0m\n" : summary + '\n';
        if (counts.fixable > 0) output += FixableLine(counts) + '\n';
      }
    }
  }
  std::string write_error;
  if (!args.write_baseline.empty()) {
    // A file found in a directory argument is an input too.
    std::vector<std::filesystem::path> checked;
    for (const FileReport& file : run.report.files) {
      if (file.file != nullptr) checked.emplace_back(file.file->Name());
    }
    const std::string clash =
        driver::OutputReplacesInput("--write-baseline", args.write_baseline, checked);
    if (!clash.empty()) return UsageError(clash);
  }
  if (!args.write_baseline.empty() && run.usage_errors.empty()) {
    const Baseline written = BaselineOfReport(run.report, report_options.base_directory);
    write_error = file_io::WriteFileAtomically(args.write_baseline, FormatBaseline(written));
    baseline_notice = std::to_string(written.entries.size()) +
                      (written.entries.size() == 1 ? " finding" : " findings") +
                      " written to the baseline " + args.write_baseline + "\n";
  }
  if (!write_error.empty()) {
    baseline_notice.clear();
  } else if (!text) {
    std::fputs(baseline_notice.c_str(), stderr);  // stdout stays machine-readable
  } else if (!args.quiet) {
    output += baseline_notice;
  }
  std::fwrite(output.data(), 1, output.size(), stdout);
  std::fflush(stdout);
  if (!write_error.empty()) {
    return UsageError("cannot write --write-baseline '" + args.write_baseline +
                      "': " + write_error);
  }
  if (run.internal_error) return kExitInternal;
  if (!run.usage_errors.empty()) return kExitUsage;
  if (!args.write_baseline.empty()) return kExitOk;  // recording findings is not failing
  return run.failed ? kExitFindings : kExitOk;
}

}  // namespace

void AddCheckCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CheckArgs>();
  auto* command = app.add_subcommand(
      "check", "Report every problem in shaders, as glslang and browsers would compile them");
  command->add_option("paths", args->paths, "Files and directories to check");
  command->add_option("--format", args->format, "text | json | sarif | github")
      ->capture_default_str();
  command->add_option("--fail-on", args->fail_on,
                      "Lowest severity that fails the check: error (default) | warning | note");
  command->add_option("--dialect", args->dialect,
                      "shadertoy | webgl1 | webgl2 | a harness dialect name | FILE.toml "
                      "(default: detected per file)");
  command->add_option("--stage", args->stage, "vertex | fragment (default: from the extension)");
  command->add_option("--target", args->target,
                      "webgl1 | webgl2: the WebGL context the shader runs in (default: webgl2 "
                      "for GLSL ES 3.00 and ShaderToy code, webgl1 for GLSL ES 1.00)");
  command->add_option("--enabled-extensions", args->enabled_extensions,
                      "NAME,NAME... | none: the #extension names the page enabled with "
                      "getExtension (default: every one the WebGL context offers)");
  command
      ->add_option("--link", args->link,
                   "VS FS: check these two files as one program (repeatable; default: "
                   "link NAME.vert with NAME.frag in the same directory)")
      ->type_size(2)
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->allow_extra_args(false);  // `--link VS FS file.glsl` checks the file too
  command->add_option("--common", args->common,
                      "ShaderToy Common code compiled before every ShaderToy pass "
                      "(default: common.glsl beside the pass)");
  command
      ->add_option("--channel", args->channels,
                   "Sampler type of a ShaderToy channel, N=2d|cube|3d (repeatable)")
      ->allow_extra_args(false);  // one value: `--channel 0=cube file.glsl` checks the file
  command->add_option("--config", args->config, "Use this .shaderport.toml instead of searching");
  command->add_flag("--no-config", args->no_config, "Ignore .shaderport.toml files");
  AddEmptyInputOptions(*command, args->allow_empty, args->no_force_exclude);
  command->add_option("-j,--jobs", args->jobs, "Files checked in parallel (default: all cores)");
  command->add_flag("--render", args->render,
                    "Also smoke-render each file that validates and check the picture");
  command->add_option("--render-size", args->render_size, "Render size in pixels (default 64)");
  command->add_option("--render-timeout", args->render_timeout,
                      "Seconds before a render is killed (default 10)");
  command->add_option("--color", args->color, "auto | always | never (NO_COLOR is honoured)")
      ->capture_default_str();
  command->add_flag("--stdin", args->stdin_input,
                    "Check the shader read from standard input (as --stdin-filename)");
  command->add_option("--stdin-filename", args->stdin_filename,
                      "The path the --stdin text stands for: its extension, directory, config "
                      "and common.glsl count as for a file there (need not exist)");
  command->add_flag("--statistics", args->statistics,
                    "Count the findings per rule (text: after the findings; other formats: on "
                    "standard error)");
  command->add_flag("-q,--quiet", args->quiet, "Print the findings only, no summary line");
  command
      ->add_option("--progress", args->progress,
                   "auto | always | never: a progress line on standard error (auto: on a "
                   "terminal, once a run lasts a second)")
      ->capture_default_str();
  command->add_option("--cache-dir", args->cache_dir,
                      "Result cache directory (default: $XDG_CACHE_HOME/shaderport or "
                      "~/.cache/shaderport)");
  command->add_flag("--no-cache", args->no_cache, "Neither read nor write the result cache");
  command->add_option("--shard", args->shard,
                      "K/N: check only the K-th of N stable parts of the files (join the "
                      "outputs with `shaderport merge`)");
  auto* baseline = command->add_option(
      "--baseline", args->baseline,
      "Report and fail only on findings not in this baseline file (see --write-baseline)");
  command
      ->add_option("--write-baseline", args->write_baseline,
                   "Record every current finding in this file and exit 0 (adopt the check "
                   "now, fail later only on new findings with --baseline)")
      ->excludes(baseline);
  command->callback([args, &exit_code] { exit_code = RunCheckCommand(*args); });
}

}  // namespace shaderport::cli
