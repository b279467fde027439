// One verdict per file: `check`, `fix` and `port` (and `report`, which shows check's
// and port's results) decide alike what a file is (driver/file_decision.h), and the
// corpus MANIFEST's dialect, stage and verdict columns hold against `check`.
#include "driver/file_decision.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "driver/check_pipeline.h"
#include "driver/html_report/build_report.h"
#include "driver/parallel_for.h"
#include "driver/port/port_file.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpusDir = fs::path(SHADERPORT_SOURCE_DIR) / "corpus";

struct Decided {
  std::string dialect, stage, harness, target;
  bool operator==(const Decided&) const = default;
};

std::ostream& operator<<(std::ostream& out, const Decided& d) {
  return out << d.dialect << "/" << d.stage << "/" << (d.harness.empty() ? "-" : d.harness) << "/"
             << d.target;
}

Decided FromReport(const FileReport& report) {
  return {report.dialect, report.stage, report.harness, report.target};
}

Decided FromDecision(const FileDecision& decision) {
  return {std::string(DialectName(decision.kind.dialect)),
          std::string(StageName(decision.kind.stage)),
          decision.harness != nullptr ? decision.harness->name : "",
          std::string(TargetName(decision.target))};
}

std::string ReadText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

struct ManifestRow {
  std::string path, dialect, stage, expect;
};

std::vector<ManifestRow> ReadManifest() {
  std::vector<ManifestRow> rows;
  std::istringstream in(ReadText(kCorpusDir / "MANIFEST"));
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::string field;
    std::istringstream cells(line);
    while (std::getline(cells, field, '\t')) fields.push_back(field);
    if (fields.size() == 5) rows.push_back({fields[0], fields[2], fields[3], fields[4]});
  }
  return rows;
}

// check's report of every file under `paths`, by file name.
std::map<std::string, FileReport> CheckReports(std::vector<fs::path> paths) {
  CheckOptions options;
  options.paths = std::move(paths);
  options.use_config = false;
  CheckRun run = RunCheck(options);
  std::map<std::string, FileReport> reports;
  for (FileReport& report : run.report.files) {
    if (report.file != nullptr) reports.emplace(std::string(report.file->Name()), report);
  }
  return reports;
}

// What `port` and `fix` decided for each file, beside what `check` decided.
void ExpectSameDecisions(const std::vector<fs::path>& files,
                         const std::map<std::string, FileReport>& checked) {
  std::mutex mutex;
  ParallelFor(files.size(), 0, [&](size_t i) {
    const fs::path& path = files[i];
    SourceManager sources;
    const PortResult ported = PortFile(path, PortOptions{}, sources);
    const PortResult fixed = FixFile(path, PortOptions{}, sources);
    const std::lock_guard lock(mutex);
    const auto it = checked.find(path.string());
    ASSERT_NE(it, checked.end()) << path;
    const Decided check = FromReport(it->second);
    EXPECT_EQ(FromDecision(ported.decision), check) << "port and check differ on " << path;
    EXPECT_EQ(FromDecision(fixed.decision), check) << "fix and check differ on " << path;
  });
}

TEST(FileDecision, CheckHoldsTheManifestColumns) {
  const std::vector<ManifestRow> rows = ReadManifest();
  ASSERT_GT(rows.size(), 30u);
  const std::map<std::string, FileReport> reports = CheckReports({kCorpusDir});
  for (const ManifestRow& row : rows) {
    const auto it = reports.find((kCorpusDir / row.path).string());
    ASSERT_NE(it, reports.end()) << row.path;
    const FileReport& report = it->second;
    if (row.dialect == "raymarch-harness") {
      EXPECT_EQ(report.harness, "raymarch-blog") << row.path;
    } else {
      EXPECT_EQ(report.dialect, row.dialect) << row.path;
    }
    EXPECT_EQ(report.stage, row.stage) << row.path;
    std::string errors;
    for (const Diagnostic& d : report.diagnostics) {
      if (d.severity == Severity::kError) errors += "\n  " + d.rule_id + ": " + d.message;
    }
    if (row.expect == "compiles") {
      EXPECT_TRUE(errors.empty()) << row.path << " compiles per MANIFEST; check says:" << errors;
    } else {
      EXPECT_FALSE(errors.empty())
          << row.path << " fails per MANIFEST (" << row.expect << "); check finds no error";
    }
  }
}

// The main job's report (tools/run-main.sh): its check column is check's verdict and
// what the MANIFEST says, its dialect and stage are check's.
TEST(FileDecision, ReportAgreesWithCheckAndTheManifest) {
  HtmlReportOptions options;
  options.paths = {kCorpusDir};
  options.size = 16;
  const HtmlReportRun run = BuildHtmlReport(options);
  const std::map<std::string, FileReport> checked = CheckReports({kCorpusDir});
  std::map<std::string, std::string> expect;
  for (const ManifestRow& row : ReadManifest())
    expect[(kCorpusDir / row.path).string()] = row.expect;
  size_t compared = 0;
  for (const ReportEntry& entry : run.report.entries) {
    const auto it = checked.find(entry.path);
    if (!entry.shader || it == checked.end()) continue;
    ++compared;
    EXPECT_EQ(entry.dialect, it->second.dialect) << entry.path;
    EXPECT_EQ(entry.stage, it->second.stage) << entry.path;
    const bool compiles = expect[entry.path] == "compiles";
    EXPECT_EQ(entry.check.status != StepStatus::kFail, compiles) << entry.path;
    if (compiles) {
      EXPECT_NE(entry.port.status, StepStatus::kFail) << entry.path;
    }
  }
  EXPECT_EQ(compared, expect.size());
}

TEST(FileDecision, CommandsDecideAlikeOnTheCorpus) {
  std::vector<fs::path> files;
  for (const ManifestRow& row : ReadManifest()) files.push_back(kCorpusDir / row.path);
  ExpectSameDecisions(files, CheckReports({kCorpusDir}));
}

// Every Image pass of the shared ShaderToy corpus as a loose file (with its Common
// tab as common.glsl beside it), as a user who copied it would have it.
// SHADERPORT_DECISION_CORPUS=records.jsonl runs the same over other records (fresh
// passes of the Shadertoys dataset), whose code stays out of the repository.
TEST(FileDecision, CommandsDecideAlikeOnSharedShaderToyPasses) {
  const char* other = std::getenv("SHADERPORT_DECISION_CORPUS");
  std::ifstream in(other != nullptr
                       ? fs::path(other)
                       : fs::path(SHADERPORT_SHARED_DIR) / "corpus-shadertoy/permissive.jsonl");
  if (!in) GTEST_SKIP() << "no shared ShaderToy corpus";
  const fs::path root =
      fs::temp_directory_path() / ("shaderport-decision-" + std::to_string(getpid()));
  fs::remove_all(root);
  std::vector<fs::path> files;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const nlohmann::json shader = nlohmann::json::parse(line);
    const fs::path dir = root / shader.value("id", "unnamed");
    fs::create_directories(dir);
    for (const nlohmann::json& pass : shader["passes"]) {
      const std::string type = pass.value("type", "");
      if (type != "image" && type != "common") continue;
      const fs::path file = dir / (type == "image" ? "image.glsl" : "common.glsl");
      std::ofstream(file, std::ios::binary) << pass.value("code", "");
      if (type == "image") files.push_back(file);
    }
  }
  ASSERT_GT(files.size(), 900u);
#if defined(__SANITIZE_ADDRESS__)
  // Sanitized builds run ten times slower: every eighth pass (the release build runs all).
  std::vector<fs::path> sample;
  for (size_t i = 0; i < files.size(); i += 8) sample.push_back(files[i]);
  files = std::move(sample);
#endif
  ExpectSameDecisions(files, CheckReports({root}));
  fs::remove_all(root);
}

TEST(FileDecision, RaymarchCodeIsCheckedBehindItsHarness) {
  const fs::path path = kCorpusDir / "raymarch/stage1-basic-scene.glsl";
  SourceManager sources;
  const SourceFile& file = sources.Add(path.string(), ReadText(path));
  const FileDecision decision = DecideFile(file, nullptr, {}, sources);
  ASSERT_NE(decision.harness, nullptr);
  EXPECT_EQ(decision.harness->name, "raymarch-blog");
  EXPECT_EQ(decision.target, model::Target::kWebGL2);
  EXPECT_NE(decision.harness_header.find("#version 300 es"), std::string::npos);
  EXPECT_NE(decision.harness_header.find("in highp vec2 uv;"), std::string::npos);
  // A forced dialect says the code stands alone: no harness is looked for.
  DecisionGiven given;
  given.dialect = Dialect::kWebGL1;
  EXPECT_EQ(DecideFile(file, nullptr, given, sources).harness, nullptr);
}

TEST(FileDecision, ChannelSampledAsCubeIsInferred) {
  SourceManager sources;
  const SourceFile& file =
      sources.Add("cube.glsl",
                  "void mainImage(out vec4 c, in vec2 f) {\n"
                  "  c = texture(iChannel1, vec3(f, 1.0)) + texture(iChannel0, f / 2.0);\n}\n");
  const FileDecision decision = DecideFile(file, nullptr, {}, sources);
  EXPECT_EQ(decision.channels[0], model::ChannelKind::k2D);
  EXPECT_EQ(decision.channels[1], model::ChannelKind::kCube);
  DecisionGiven given;
  given.channels[1] = model::ChannelKind::k3D;
  EXPECT_EQ(DecideFile(file, nullptr, given, sources).channels[1], model::ChannelKind::k3D);
}

}  // namespace
}  // namespace shaderport::driver
