// What a user can set for one `shaderport check` run.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "diag/diagnostic.h"
#include "driver/dialect.h"
#include "driver/read_input.h"
#include "driver/shard.h"
#include "model/channel_kind.h"
#include "model/harness_dialect.h"
#include "model/webgl_extensions.h"
#include "validate/shadertoy_contract.h"

namespace shaderport::driver {

struct CheckOptions {
  std::vector<std::filesystem::path> paths;
  std::optional<Dialect> dialect;     // --dialect: overrides detection and config
  std::optional<model::Stage> stage;  // --stage
  std::optional<model::Target> target;
  // --enabled-extensions: the #extension names the page enabled (default: all the
  // context offers).
  model::EnabledExtensions enabled_extensions;
  // --link VS FS: programs to link; when empty, vertex and fragment files with the
  // same stem in the same directory are linked.
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>>
      links;                                    // --target: the WebGL context (default: by version)
  std::optional<std::filesystem::path> common;  // --common: ShaderToy Common for every pass
  model::GivenChannelKinds channels{};          // --channel N=2d|cube|3d; nullopt: inferred
  // --dialect NAME|FILE.toml naming a harness dialect (rules/dialects/): the code is
  // checked as that host composes it.
  const model::HarnessDialect* harness = nullptr;
  std::optional<std::filesystem::path> config;  // --config: instead of searching upward
  bool use_config = true;                       // --no-config
  // The config's include/exclude globs apply to files named on the command line
  // too (--no-force-exclude: only to files found in directories).
  bool force_exclude = true;
  std::optional<Severity> fail_on;  // --fail-on: overrides the config's
  unsigned jobs = 0;                // 0: every core
  // --render: smoke-render every file that validates and check the picture.
  bool render = false;
  int render_size = 64;        // --render-size: width and height in pixels
  double render_timeout = 10;  // seconds before a render is killed
  // --stdin: check these contents (read by the caller) as the file `name`, which
  // need not exist; its extension and directory count as for a real file there.
  // `paths` is then ignored.
  struct InMemoryFile {
    std::filesystem::path name;
    InputText contents;
  };
  std::optional<InMemoryFile> in_memory;
  // Called after each file is done (checked, or rendered with --render), one call at
  // a time (from the worker threads, so it must not assume a thread); the caller
  // decides what to show. `done` counts up to `total`.
  std::function<void(size_t done, size_t total)> progress;
  // The result cache (docs/cli.md): off when unset (--no-cache). `tool_identity`
  // names this build of shaderport, so a rebuilt binary never reads stale entries.
  std::optional<std::filesystem::path> cache_directory;
  std::string tool_identity;
  std::optional<ShardSpec> shard;  // --shard K/N: only this shard's files
  // `explain-file`: decide what each file is (FileReport::decision) and stop there:
  // no glslang, no links, no renders, no cache.
  bool explain_only = false;
  // Free the text of each file that comes out with no finding as soon as it is checked
  // (`check`: its reports print findings only). Off for callers that show every file.
  bool release_clean_texts = false;
};

}  // namespace shaderport::driver
