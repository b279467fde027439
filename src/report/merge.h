// `shaderport merge`: joins the JSON or SARIF outputs of several `check` runs
// (typically the shards of one repository) into the report a single run over all
// their files prints, byte for byte: files in path order, one SARIF rule table
// with its indices, fingerprint occurrences counted over the whole report and the
// JSON summary recounted.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"
#include "report/check_report.h"

namespace shaderport {

enum class MergeFormat { kJson, kSarif };

struct MergeInput {
  std::string name;  // for messages
  std::string text;
};

struct MergeResult {
  std::string output;               // the merged report; empty when `errors` is not
  std::vector<std::string> errors;  // usage errors: unreadable, mixed formats or versions
  std::optional<Severity> worst;    // the most severe finding, if any
};

// `format` asserts the inputs' format; without it the first input's decides.
MergeResult MergeReports(const std::vector<MergeInput>& inputs,
                         std::optional<MergeFormat> format = std::nullopt);

// The SARIF property that lets merge put the results of several shards back in
// the single run's file order (SARIF results do not say which checked file they
// belong to: a finding in ShaderToy Common code points into Common).
inline constexpr const char* kSarifShardProperty = "shaderport/files";

// Which shard of how many an output holds: "K/N" in the JSON report's `shard`
// and in the SARIF run's properties, so that merge can refuse a set of shards
// with one missing or repeated (a CI job that died must not pass the gate).
inline constexpr const char* kSarifShardSpecProperty = "shaderport/shard";

struct ShardOfRun {
  unsigned index = 1;  // 1-based
  unsigned count = 1;
};

// `check --shard K/N`: `output` (FormatJson or FormatSarif of `report`) with the
// shard written in; for SARIF also the file index above on its run, listing
// each file with findings and how many results it has.
std::string AddShardMarkers(std::string_view output, MergeFormat format, const CheckReport& report,
                            ShardOfRun shard);

}  // namespace shaderport
