// The hostile-input table of docs/limits.md, every row through every command: check,
// fix, port with each --emit (and --opt O), render, report, merge and dump, each under
// the 2 GiB address-space cap and the wall-time bound of bounded_run.h. None may die of
// a signal, exit 3 (internal error) or hang. A row past one of shaderport's own limits
// must be stopped there by every command (the limit's rule id in what it prints or
// writes), as `check` stops: no text that hit a limit reaches glslang, SPIRV-Tools,
// SPIRV-Cross or Mesa. Runs go two at a time; the rows are the compact set that covers
// each limit and each kind of byte-level oddity. Sanitizer builds leave out the rows of
// millions of tokens and the commands that run Mesa.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "bounded_run.h"
#include "temp_project.h"

namespace shaderport::testing {
namespace {

struct Row {
  std::string file;
  std::string text;
  std::string breach;  // the limit's rule id every command reports, or empty
  bool heavy = false;  // millions of tokens: left to the other builds under sanitizers
};

Row Plain(std::string file, std::string text) {
  return {std::move(file), std::move(text), "", false};
}

std::string PassWith(const std::string& body) {
  return "void mainImage(out vec4 c, in vec2 p) {\n" + body + "\n}\n";
}

std::vector<Row> Rows() {
  std::vector<Row> rows;
  rows.push_back(Plain("empty.frag", ""));
  std::string png = "\x89PNG\r\n\x1a\n";
  for (int i = 0; i < 4096; ++i) png += static_cast<char>((i * 7919) & 0xff);
  rows.push_back(Plain("binary.frag", png));
  rows.push_back(Plain("nul.frag", PassWith(std::string("  c = vec4(1.0);") + '\0')));
  rows.push_back(Plain("utf8.frag", PassWith("  float x = \xc3\x28;\n  c = vec4(x);")));
  rows.push_back(Plain("bom-cr.frag", "\xef\xbb\xbf// cr\r" + PassWith("  c = vec4(1.0);\r")));
  rows.push_back(Plain("identifier.frag", PassWith("  float " + std::string(1u << 20, 'a') +
                                                   " = 1.0;\n  c = vec4(1.0);")));
  rows.push_back(Plain("recursive.glsl", "#define A A + 1.0\n#define B C\n#define C B\n" +
                                             PassWith("  c = vec4(A, B, 0.0, 1.0);")));
  rows.push_back(
      Plain("line.glsl", "#line 4294967295\n" + PassWith("  c = vec4(undefined_name);")));
  // One '}' missing: the fixes once never settled (100 returns written).
  rows.push_back(Plain("brace.glsl", "float f(float x) {\n  if (x > 0.0) {\n    return x;\n}\n" +
                                         PassWith("  c = vec4(f(p.x));")));
  // f_i calls f_(i-1) twice, 30 deep: 2^30 copies once inlined.
  std::string calls = "float f0(float x) { return sin(x) * 1.5 + x; }\n";
  for (int i = 1; i <= 30; ++i) {
    const std::string g = "f" + std::to_string(i - 1);
    calls +=
        "float f" + std::to_string(i) + "(float x) { return " + g + "(x) + " + g + "(x * 0.5); }\n";
  }
  rows.push_back(Plain("inlining.glsl", calls + PassWith("  c = vec4(f30(p.x));")));
  // As deep as browsers' parsers go (docs/limits.md, "Nesting"), not past it: trees
  // thousands of levels deep reach every command's rules, transforms and walks.
  const auto repeat = [](const std::string& s, int n) {
    std::string out;
    for (int i = 0; i < n; ++i) out += s;
    return out;
  };
  rows.push_back(Plain("parens.frag", PassWith("  float x = " + repeat("(", 9900) + "p.x" +
                                               repeat(")", 9900) + ";\n  c = vec4(x);")));
  rows.push_back(Plain("negations.frag", PassWith("  float x = " + repeat("-(", 4900) + "p.x" +
                                                  repeat(")", 4900) + ";\n  c = vec4(x);")));
  // Calls stop at 2,000: SPIRV-Tools names glslang's per-call temporaries `param_N` in
  // time quadratic in their number (FriendlyNameMapper, also inside its validator).
  rows.push_back(Plain("calls.frag", "float f(float x) { return x; }\n" +
                                         PassWith("  float x = " + repeat("f(", 2000) + "p.x" +
                                                  repeat(")", 2000) + ";\n  c = vec4(x);")));
  rows.push_back(Plain(
      "conditionals.frag",
      PassWith("  float x = " + repeat("p.x > 0.5 ? p.y : ", 1600) + "0.0;\n  c = vec4(x);")));
  rows.push_back(
      Plain("if-chain.frag",
            PassWith("  c = vec4(0.0);\n  " + repeat("if (p.x > 0.5) ", 1600) + "c = vec4(1.0);")));
  rows.push_back(Plain("blocks.frag", PassWith("  c = vec4(0.0);\n  " + repeat("{ ", 3000) +
                                               "c = vec4(1.0);" + repeat(" }", 3000))));
  rows.push_back(Plain("if-directive.frag", "#if " + repeat("(", 9900) + "1" + repeat(")", 9900) +
                                                "\n" + PassWith("  c = vec4(1.0);") + "#endif\n"));
  // A chain a+a+... 20,000 deep: past the SPIR-V leg's depth limit, under the parser's.
  std::string chain = "  float a = p.x;\n  c = vec4(a";
  for (int i = 0; i < 20'000; ++i) chain += "+a";
  rows.push_back(Plain("chain.frag", PassWith(chain + ");")));
  rows.push_back({"braces.frag", PassWith(std::string(100000, '{') + std::string(100000, '}')),
                  "syntax/nesting-too-deep", false});
  std::string ifs;
  for (int i = 0; i < 10000; ++i) ifs += "#if 1\n";
  ifs += PassWith("  c = vec4(1.0);");
  for (int i = 0; i < 10000; ++i) ifs += "#endif\n";
  rows.push_back({"ifs.frag", ifs, "preprocessor/conditional-too-deep", false});
  // About 850 bytes: M15 asks for 4^15 copies.
  std::string bomb = "#define M0 1.0+\n";
  for (int i = 1; i <= 15; ++i) {
    const std::string m = "M" + std::to_string(i - 1);
    bomb += "#define M" + std::to_string(i) + " " + m + " " + m + " " + m + " " + m + "\n";
  }
  rows.push_back({"bomb.frag", bomb + PassWith("  c = vec4(M15 1.0);"),
                  "preprocessor/expansion-too-large", true});
  // 3 KB, 1.2 million tokens once expanded: under the expansion limit, over glslang's.
  std::string flat = "#define A";
  for (int i = 0; i < 500; ++i) flat += " a +";
  std::string uses;
  for (int i = 0; i < 1200; ++i) uses += "A ";
  rows.push_back({"flat.frag",
                  flat + "\n" + PassWith("  float a = 1.0;\n  c = vec4(" + uses + "a);"),
                  "preprocessor/output-too-large", true});
  // 6 MB, 3 million tokens.
  std::string tokens = "  float a = 1.0;\n  float x = a";
  for (int i = 0; i < 1'500'000; ++i) tokens += " + a";
  rows.push_back(
      {"tokens.frag", PassWith(tokens + ";\n  c = vec4(x);"), "lex/too-many-tokens", true});
  return rows;
}

// Every command on `file`; outputs are named after it, so that runs never share one.
std::vector<std::vector<std::string>> Commands(const std::string& file) {
  std::vector<std::vector<std::string>> commands = {
      {"check", "--no-cache", file},
      {"fix", "--diff", file},
      {"fix", "-o", file + ".fixed", file},
      {"port", "-o", file + ".ported", file},
      {"port", "--emit", "spirv", "--opt", "O", "-o", file + ".opt.spv", file},
      {"render", file, "-o", file + ".png", "--hermetic"},
      {"report", "--html", file + ".report.html", "--hermetic", file},
      {"merge", file},
      {"dump", "--types", file},
      {"dump", "--pp-tokens", file},
  };
  for (const std::string emit :
       {"spirv", "spvasm", "hlsl", "msl", "essl-roundtrip", "reflect", "html"}) {
    commands.push_back({"port", "--emit", emit, "-o", file + "." + emit, file});
  }
  return commands;
}

struct Job {
  const Row* row;
  std::vector<std::string> args;
  BoundedRun run;
};

const std::vector<Row>& AllRows() {
  static const std::vector<Row> rows = Rows();
  return rows;
}

// One test a row, so that ctest spreads the rows over its jobs.
class HostileEveryCommand : public ::testing::TestWithParam<size_t> {};

TEST_P(HostileEveryCommand, NoSignalNoInternalErrorNoHangAndLimitsStopEveryCommand) {
  const Row& row = AllRows()[GetParam()];
  if (row.heavy && kSanitizedBuild) GTEST_SKIP() << "millions of tokens: left to other builds";
  TempProject project("hostile-every-" + std::to_string(GetParam()));
  project.Write(row.file, row.text);
  std::vector<Job> jobs;
  for (std::vector<std::string>& args : Commands(row.file)) {
    // Under sanitizers only shaderport's own code gets slower: Mesa (render, report) is
    // left to the other builds, to keep CI's sanitizer job short.
    if (kSanitizedBuild && (args[0] == "render" || args[0] == "report")) continue;
    jobs.push_back({&row, args, {}});
  }
  std::atomic<size_t> next = 0;
  BoundedRunOptions options;
  options.directory = project.Root();
  auto worker = [&] {
    for (size_t i = next++; i < jobs.size(); i = next++)
      jobs[i].run = RunBounded(jobs[i].args, options);
  };
  std::thread second(worker);
  worker();
  second.join();

  // The slowest runs, for the CI log: the bounds are per run.
  std::vector<const Job*> slowest;
  for (const Job& job : jobs) slowest.push_back(&job);
  std::sort(slowest.begin(), slowest.end(),
            [](const Job* a, const Job* b) { return a->run.seconds > b->run.seconds; });
  slowest.resize(std::min<size_t>(slowest.size(), 3));
  std::printf("%s: %zu runs; slowest:\n", row.file.c_str(), jobs.size());
  for (const Job* job : slowest) {
    std::printf("  %.1f s, %ld MiB: %s\n", job->run.seconds, job->run.max_rss_kib >> 10,
                ::testing::PrintToString(job->args).c_str());
  }
  for (const Job& job : jobs) {
    const std::string what = ::testing::PrintToString(job.args);
    const std::string printed = job.run.Printed().substr(0, 1500);
    EXPECT_FALSE(job.run.timed_out) << what;
    EXPECT_LT(job.run.exit_code, 128) << what << " died of signal " << job.run.exit_code - 128;
    EXPECT_NE(job.run.exit_code, 3) << what << "\n" << printed;
    if (job.row->breach.empty() || job.args[0] == "merge") continue;
    // report writes its findings into the page; every other command prints them.
    const std::string said = job.args[0] == "report"
                                 ? ReadWholeFile(project.Root() / (job.row->file + ".report.html"))
                                 : job.run.Printed();
    EXPECT_NE(said.find(job.row->breach), std::string::npos)
        << what << " should stop at " << job.row->breach << "\n"
        << printed;
  }
}

INSTANTIATE_TEST_SUITE_P(Rows, HostileEveryCommand, ::testing::Range<size_t>(0, AllRows().size()),
                         [](const ::testing::TestParamInfo<size_t>& row_info) {
                           std::string name = AllRows()[row_info.param].file;
                           for (char& c : name) {
                             if (c == '.' || c == '-') c = '_';
                           }
                           return name;
                         });

// The fixes of a file with one '}' missing settle: `fix -i` leaves it as it was.
TEST(HostileUnclosedBody, FixInPlaceWritesNothing) {
  TempProject project("hostile-brace");
  const std::string text =
      "float f(float x) {\n  if (x > 0.0) {\n    return x;\n}\n" + PassWith("  c = vec4(f(p.x));");
  project.Write("brace.glsl", text);
  BoundedRunOptions options;
  options.directory = project.Root();
  const BoundedRun run = RunBounded({"fix", "-i", "brace.glsl"}, options);
  EXPECT_EQ(run.exit_code, 1) << run.Printed();
  EXPECT_EQ(run.Printed().find("internal/error"), std::string::npos) << run.Printed();
  EXPECT_EQ(ReadWholeFile(project.Root() / "brace.glsl"), text);
}

}  // namespace
}  // namespace shaderport::testing
