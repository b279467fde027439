// Our in-process validation must agree with the glslangValidator CLI on every
// stage of the WebGL conformance cases: same verdict, same set of error lines.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>

#include "validate/glslang_log.h"
#include "validate/validate_test_util.h"

namespace shaderport::validate {
namespace {

namespace fs = std::filesystem;

struct StageCase {
  std::string id;    // "<case id> vertex|fragment"
  std::string file;  // path written for the CLI
  std::string text;
  model::Stage stage;
};

struct Verdict {
  bool ran = false;  // the CLI printed a section for the file
  bool crashed = false;
  bool accepted = true;
  std::set<uint32_t> error_lines;
  // Every error's line as shaderport reports it, including messages glslang gives
  // no line, which shaderport places at the start of the file.
  std::set<uint32_t> all_error_lines;
};

std::string FindOnPath(const std::string& program) {
  const char* path = getenv("PATH");
  std::string dirs = path ? path : "";
  size_t start = 0;
  while (start <= dirs.size()) {
    const size_t end = std::min(dirs.find(':', start), dirs.size());
    const fs::path candidate = fs::path(dirs.substr(start, end - start)) / program;
    if (access(candidate.c_str(), X_OK) == 0) return candidate.string();
    start = end + 1;
  }
  return "";
}

// Runs one CLI process over `files`; returns false when it died from a signal.
bool RunCli(const std::string& cli, const std::vector<const StageCase*>& files,
            std::map<std::string, Verdict>& verdicts) {
  std::string command = cli + " -C";
  for (const StageCase* c : files) command += " '" + c->file + "'";
  command += " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return false;
  std::string output;
  char buffer[65536];
  size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) output.append(buffer, n);
  const int status = pclose(pipe);
  // The shell reports a child killed by a signal as exit status 128 + signal.
  if (WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) > 128)) return false;
  std::set<std::string> names;
  for (const StageCase* c : files) names.insert(c->file);
  // Each file's name is printed on its own line, followed by its messages.
  // With a single file the CLI prints no name at all.
  std::string current = files.size() == 1 ? files[0]->file : "";
  std::string section;
  auto flush = [&] {
    if (current.empty()) return;
    Verdict& verdict = verdicts[current];
    verdict.ran = true;
    for (const GlslangMessage& m : ParseGlslangLog(section)) {
      if (m.severity != Severity::kError) continue;
      verdict.accepted = false;
      if (m.line > 0) verdict.error_lines.insert(m.line);
    }
  };
  size_t pos = 0;
  while (pos < output.size()) {
    size_t end = output.find('\n', pos);
    if (end == std::string::npos) end = output.size();
    const std::string line = output.substr(pos, end - pos);
    pos = end + 1;
    if (names.count(line)) {
      flush();
      current = line;
      section.clear();
    } else {
      section += line + "\n";
    }
  }
  flush();
  return true;
}

// A crash loses the whole process's buffered output: bisect to find the culprit.
void RunCliBisecting(const std::string& cli, const std::vector<const StageCase*>& files,
                     std::map<std::string, Verdict>& verdicts) {
  if (files.empty() || RunCli(cli, files, verdicts)) return;
  for (const StageCase* c : files) verdicts.erase(c->file);
  if (files.size() == 1) {
    verdicts[files[0]->file].crashed = true;
    return;
  }
  const auto middle = files.begin() + static_cast<std::ptrdiff_t>(files.size() / 2);
  RunCliBisecting(cli, {files.begin(), middle}, verdicts);
  RunCliBisecting(cli, {middle, files.end()}, verdicts);
}

std::map<std::string, Verdict> CliVerdicts(const std::string& cli,
                                           const std::vector<StageCase>& cases) {
  std::map<std::string, Verdict> verdicts;
  constexpr size_t kBatch = 500;  // bounds the command line and the work lost to a crash
  for (size_t begin = 0; begin < cases.size(); begin += kBatch) {
    std::vector<const StageCase*> batch;
    for (size_t i = begin; i < std::min(cases.size(), begin + kBatch); ++i) {
      batch.push_back(&cases[i]);
    }
    RunCliBisecting(cli, batch, verdicts);
  }
  return verdicts;
}

std::vector<StageCase> LoadCases(const fs::path& dir) {
  std::ifstream in(std::string(SHADERPORT_SHARED_DIR) + "/conformance/webgl-cts.jsonl");
  std::vector<StageCase> cases;
  std::string line;
  for (int index = 0; std::getline(in, line); ++index) {
    const auto json = nlohmann::json::parse(line);
    for (model::Stage stage : {model::Stage::kVertex, model::Stage::kFragment}) {
      const bool vertex = stage == model::Stage::kVertex;
      StageCase c;
      c.id = json.at("id").get<std::string>() + (vertex ? " vertex" : " fragment");
      c.file = (dir / (std::to_string(index) + (vertex ? ".vert" : ".frag"))).string();
      c.text = json.at(vertex ? "vertex" : "fragment").get<std::string>();
      c.stage = stage;
      std::ofstream(c.file, std::ios::binary) << c.text;
      cases.push_back(std::move(c));
    }
  }
  return cases;
}

Verdict OurVerdict(const StageCase& c) {
  SourceManager sources;
  const ValidationResult result = testing::ValidateText(sources, c.text, c.stage, 100);
  Verdict verdict;
  verdict.ran = true;
  verdict.crashed = result.crashed;
  verdict.accepted = result.Accepted(false);
  // Without generated parts each message is one diagnostic, in order. Messages
  // glslang gives no line (e.g. "#version: statement must appear first") are
  // placed at the file's start, but the CLI's output has no line to compare.
  if (!result.crashed) {
    EXPECT_EQ(result.diagnostics.size(), result.messages.size()) << c.id;
  }
  for (size_t i = 0; i < result.diagnostics.size() && i < result.messages.size(); ++i) {
    const Diagnostic& d = result.diagnostics[i];
    if (d.severity != Severity::kError) continue;
    const uint32_t line = testing::Where(sources, d.range).line;
    verdict.all_error_lines.insert(line);
    if (result.messages[i].message.line > 0) verdict.error_lines.insert(line);
  }
  return verdict;
}

std::string Lines(const std::set<uint32_t>& lines) {
  std::string out;
  for (uint32_t line : lines) out += std::to_string(line) + " ";
  return out;
}

// Runs the real `shaderport check` binary over the directory and reads its JSON.
std::map<std::string, Verdict> CheckVerdicts(const fs::path& dir) {
  const std::string command = "cd '" + dir.string() + "' && '" + SHADERPORT_BINARY +
                              "' check --no-config --format json -j 2 . 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  std::string output;
  char buffer[65536];
  size_t n;
  while (pipe != nullptr && (n = fread(buffer, 1, sizeof buffer, pipe)) > 0) {
    output.append(buffer, n);
  }
  if (pipe != nullptr) pclose(pipe);
  std::map<std::string, Verdict> verdicts;
  const auto json = nlohmann::json::parse(output, nullptr, false);
  if (json.is_discarded()) return verdicts;
  for (const auto& file : json.at("files")) {
    Verdict& verdict = verdicts[fs::path(file.at("path").get<std::string>()).filename().string()];
    verdict.ran = true;
    for (const auto& d : file.at("diagnostics")) {
      if (d.at("severity") != "error") continue;
      verdict.accepted = false;
      verdict.all_error_lines.insert(
          d.at("location").at("range").at("start").at("line").get<uint32_t>());
    }
  }
  return verdicts;
}

TEST(ConformanceAgreementTest, VerdictsAndErrorLinesMatchGlslangValidator) {
  const std::string cli = FindOnPath("glslangValidator");
  if (cli.empty()) GTEST_SKIP() << "glslangValidator is not on PATH: agreement not checked";
  char dir_template[] = "/tmp/shaderport-cts-XXXXXX";
  ASSERT_NE(mkdtemp(dir_template), nullptr);
  const fs::path dir = dir_template;
  const std::vector<StageCase> cases = LoadCases(dir);
  ASSERT_GE(cases.size(), 4000u);

  const auto start = std::chrono::steady_clock::now();
  auto seconds_since_start = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  auto cli_future = std::async(std::launch::async, [&] {
    auto verdicts = CliVerdicts(cli, cases);
    std::printf("glslangValidator done after %.2f s\n", seconds_since_start());
    return verdicts;
  });
  std::vector<Verdict> ours(cases.size());
  std::thread helper([&] {
    for (size_t i = 1; i < cases.size(); i += 2) ours[i] = OurVerdict(cases[i]);
  });
  for (size_t i = 0; i < cases.size(); i += 2) ours[i] = OurVerdict(cases[i]);
  helper.join();
  std::printf("in-process validation done after %.2f s\n", seconds_since_start());
  const auto theirs = cli_future.get();
  const std::map<std::string, Verdict> checked = CheckVerdicts(dir);
  std::printf("shaderport check done after %.2f s\n", seconds_since_start());
  fs::remove_all(dir);

  size_t agreed = 0, accepted = 0, cli_crashes = 0, check_agreed = 0;
  for (size_t i = 0; i < cases.size(); ++i) {
    const auto it = theirs.find(cases[i].file);
    ASSERT_NE(it, theirs.end()) << cases[i].id;
    const Verdict& cli_verdict = it->second;
    if (cli_verdict.crashed) {
      // glslangValidator itself crashes here; we must report that, not crash.
      ++cli_crashes;
      std::printf("glslangValidator crashed on %s; shaderport reported glslang/crashed: %s\n",
                  cases[i].id.c_str(), ours[i].crashed ? "yes" : "no");
      EXPECT_TRUE(ours[i].crashed) << cases[i].id;
      continue;
    }
    EXPECT_TRUE(cli_verdict.ran) << cases[i].id;
    EXPECT_FALSE(ours[i].crashed) << cases[i].id;
    EXPECT_EQ(ours[i].accepted, cli_verdict.accepted) << cases[i].id;
    EXPECT_EQ(Lines(ours[i].error_lines), Lines(cli_verdict.error_lines)) << cases[i].id;
    if (ours[i].accepted == cli_verdict.accepted &&
        ours[i].error_lines == cli_verdict.error_lines) {
      ++agreed;
    }
    accepted += ours[i].accepted ? 1 : 0;
    // The whole `check` pipeline adds WebGL's rules and lowers glslang's known
    // false errors, so its verdict is compared with the browser's in
    // tests/unit/driver/webgl_conformance_test.cpp; here it is only counted.
    const auto check_it = checked.find(fs::path(cases[i].file).filename().string());
    ASSERT_NE(check_it, checked.end()) << cases[i].id;
    if (check_it->second.accepted == ours[i].accepted &&
        check_it->second.all_error_lines == ours[i].all_error_lines) {
      ++check_agreed;
    }
  }
  std::printf(
      "%zu stages: %zu agree with glslangValidator (%zu accepted), %zu crash it; "
      "shaderport check agrees on %zu\n",
      cases.size(), agreed, accepted, cli_crashes, check_agreed);
  EXPECT_EQ(cli_crashes, 1u);  // macro-expansion-tricky.html#0 fragment
}

}  // namespace
}  // namespace shaderport::validate
