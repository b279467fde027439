// The "Hostile input" table of docs/limits.md, row by row through the real binary:
// each input gets a diagnostic naming the file and a stable rule id, exit 1 or 2
// (never 3 or a signal), within a wall-time bound and (outside ASan) a 2 GiB
// address-space limit.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "bounded_run.h"
#include "temp_project.h"

namespace shaderport::testing {
namespace {

namespace fs = std::filesystem;

constexpr double kMaxSeconds = static_cast<double>(kBoundedRunTimeLimit.count());

// A ShaderToy pass whose third line has an undeclared name at column 13.
std::string PassWithErrorOnLine3(const std::string& newline) {
  return "void mainImage(out vec4 c, in vec2 p) {" + newline + "  c = vec4(1.0);" + newline +
         "  float y = undefined_name;" + newline + "}" + newline;
}

class HostileInputTest : public ::testing::Test {
 protected:
  BoundedRun Run(std::vector<std::string> args, BoundedRunOptions options = {}) {
    options.directory = project_.Root();
    return RunBounded(args, options);
  }

  // Runs each command on `name` and expects `expected` (e.g. "[input/binary]" or
  // "cr.frag:3:13") in what it prints, exit `exit_code`, and the time bound.
  void Expect(const std::vector<std::vector<std::string>>& commands, const std::string& expected,
              int exit_code = 1) {
    for (const std::vector<std::string>& args : commands) {
      const BoundedRun run = Run(args);
      const std::string what = ::testing::PrintToString(args);
      EXPECT_FALSE(run.timed_out) << what;
      EXPECT_EQ(run.exit_code, exit_code) << what << "\n" << run.Printed().substr(0, 2000);
      EXPECT_NE(run.Printed().find(expected), std::string::npos)
          << what << " should print " << expected << "\n"
          << run.Printed().substr(0, 2000);
      EXPECT_LT(run.seconds, kMaxSeconds) << what;
    }
  }

  static std::vector<std::vector<std::string>> CheckFixPort(const std::string& name) {
    return {{"check", name}, {"fix", "--diff", name}, {"port", "-o", "ported.frag", name}};
  }

  TempProject project_{"hostile"};
};

TEST_F(HostileInputTest, InvalidUtf8InCodeIsAGlslangErrorOnItsLine) {
  project_.Write("bad.frag",
                 "void mainImage(out vec4 c, in vec2 p) {\n  c = vec4(1.0); // caf\xe9 \xff\n"
                 "  float x = \xc3\x28;\n}\n");
  Expect({{"check", "bad.frag"}, {"fix", "--diff", "bad.frag"}}, "bad.frag:3:3: error");
  Expect({{"check", "bad.frag"}}, "[glslang/error]");
  Expect({{"port", "-o", "ported.frag", "bad.frag"}}, "bad.frag:");
}

TEST_F(HostileInputTest, InvalidUtf8OnlyInACommentIsAccepted) {
  project_.Write("comment.frag", "// caf\xe9 \xff\xfe\n" + PassWithErrorOnLine3("\n"));
  Expect({{"check", "comment.frag"}}, "comment.frag:4:13: error");
}

TEST_F(HostileInputTest, NulByteInCodeOrCommentIsBinary) {
  project_.Write(
      "code.frag",
      std::string("void mainImage(out vec4 c, in vec2 p) {\n  c = vec4(1.0);") + '\0' + "\n}\n");
  project_.Write("comment.frag",
                 std::string("// a comment ") + '\0' + "\n" + PassWithErrorOnLine3("\n"));
  Expect(CheckFixPort("code.frag"), "code.frag:1:1: error: file looks like binary data");
  Expect(CheckFixPort("comment.frag"), "comment.frag:1:1: error: file looks like binary data");
  Expect({{"check", "code.frag"}}, "[input/binary]");
}

// Skipped as clang and a browser's TextDecoder do; glslang, given the mark, stops
// at 1:1 ("'\xef': unexpected token"), as it used to here.
TEST_F(HostileInputTest, Utf8ByteOrderMarkIsSkippedAndKeptByFix) {
  project_.Write("bom.frag", "\xef\xbb\xbf" + PassWithErrorOnLine3("\n"));
  Expect(CheckFixPort("bom.frag"), "bom.frag:3:13: error: 'undefined_name'");
  const BoundedRun check = Run({"check", "bom.frag"});
  EXPECT_EQ(check.out.find("bom.frag:1:"), std::string::npos) << check.out;
  project_.Write("fixable.frag",
                 "\xef\xbb\xbfvoid mainImage(out vec4 c, in vec2 p) {\n"
                 "  vec3 v = 1.0;\n  c = vec4(v, 1.0);\n}\n");
  const BoundedRun fix = Run({"fix", "-i", "fixable.frag"});
  EXPECT_EQ(fix.exit_code, 0) << fix.Printed();
  EXPECT_EQ(ReadWholeFile(project_.Root() / "fixable.frag"),
            "\xef\xbb\xbfvoid mainImage(out vec4 c, in vec2 p) {\n"
            "  vec3 v = vec3(1.0);\n  c = vec4(v, 1.0);\n}\n");
  project_.Write("only-mark.frag", "\xef\xbb\xbf");
  Expect({{"check", "only-mark.frag"}}, "only-mark.frag:1:1: error: file is empty [input/empty]");
}

TEST_F(HostileInputTest, EmptyFile) {
  project_.Write("empty.frag", "");
  Expect(CheckFixPort("empty.frag"), "empty.frag:1:1: error: file is empty");
  Expect({{"check", "empty.frag"}}, "[input/empty]");
}

TEST_F(HostileInputTest, BinaryFile) {
  std::string png = "\x89PNG\r\n\x1a\n";
  for (int i = 0; i < 4096; ++i) png += static_cast<char>((i * 7919) & 0xff);
  project_.Write("image.frag", png);
  Expect(CheckFixPort("image.frag"), "image.frag:1:1: error: file looks like binary data");
  Expect({{"check", "image.frag"}}, "[input/binary]");
}

// glslang counted only LF: with CR-only endings every finding was put on 1:1.
TEST_F(HostileInputTest, CrOnlyLineEndingsKeepLineAndColumn) {
  project_.Write("cr.frag", "// first line\r" + PassWithErrorOnLine3("\r"));
  Expect(CheckFixPort("cr.frag"), "cr.frag:4:13: error: 'undefined_name'");
}

TEST_F(HostileInputTest, CrlfLineEndingsKeepLineAndColumn) {
  project_.Write("crlf.frag", "// first line\r\n" + PassWithErrorOnLine3("\r\n"));
  Expect(CheckFixPort("crlf.frag"), "crlf.frag:4:13: error: 'undefined_name'");
  // fix keeps CRLF: its diff of an untouched line would otherwise show.
  const BoundedRun fixed = Run({"fix", "crlf.frag"});
  EXPECT_NE(fixed.out.find("  c = vec4(1.0);\r\n"), std::string::npos) << fixed.out;
}

TEST_F(HostileInputTest, FiftyMegabyteFileCostsNeitherTimeNorMemory) {
  {
    std::ofstream out(project_.Root() / "huge.frag", std::ios::binary);
    out.seekp(50 << 20);
    out.put('\n');
  }
  Expect(CheckFixPort("huge.frag"),
         "huge.frag:1:1: error: file is 50.1 MiB, larger than the 8 MiB limit");
  const BoundedRun run = Run({"check", "huge.frag"});
  EXPECT_LT(run.max_rss_kib, 256 << 10) << "the file must not be read";
}

TEST_F(HostileInputTest, TenMegabyteSingleLineIsTooLarge) {
  std::string line = "void mainImage(out vec4 c, in vec2 p) { float a = 0.0;";
  while (line.size() < (10u << 20)) line += " a += 1.0;";
  project_.Write("line.frag", line + " c = vec4(a); }\n");
  Expect(CheckFixPort("line.frag"), "[input/too-large]");
}

// Just under the size limit, one line of 3 million tokens: the token cap stops it.
TEST_F(HostileInputTest, SevenMegabyteSingleLineStopsAtTheTokenLimit) {
  std::string line = "void mainImage(out vec4 c, in vec2 p) { float a = 0.0;";
  while (line.size() < (15u << 19)) line += " a += 1.0;";
  project_.Write("line.frag", line + " c = vec4(a); }\n");
  Expect({{"check", "line.frag"}}, "[lex/too-many-tokens]");
}

TEST_F(HostileInputTest, MegabyteIdentifier) {
  const std::string name(1u << 20, 'a');
  project_.Write("ident.frag", "void mainImage(out vec4 c, in vec2 p) {\n  float " + name +
                                   " = 1.0;\n  c = vec4(" + name + ");\n}\n");
  Expect(CheckFixPort("ident.frag"), "ident.frag:2:3: error: name too long [glslang/error]");
}

TEST_F(HostileInputTest, HundredThousandNestedBraces) {
  project_.Write("braces.frag", "void mainImage(out vec4 c, in vec2 p) {\n" +
                                    std::string(100000, '{') + std::string(100000, '}') + "\n}\n");
  Expect({{"check", "braces.frag"}}, "braces.frag:2:3332: error: nesting too deep");
  Expect(CheckFixPort("braces.frag"), "braces.frag:2:");
}

TEST_F(HostileInputTest, HundredThousandNestedParenthesesUnderFixAndPort) {
  project_.Write("parens.frag", "void mainImage(out vec4 c, in vec2 p) {\n  float x = " +
                                    std::string(100000, '(') + "1.0" + std::string(100000, ')') +
                                    ";\n  c = vec4(x);\n}\n");
  Expect(CheckFixPort("parens.frag"), "parens.frag:2:");
}

// 400,000 terms (800 KB) in one expression: glslang's SPIR-V generator recursed once per
// term and overflowed its 256 MiB stack (SIGSEGV) in port --emit and in the render's
// optimiser; check, fix and port to WebGL2 were fine.
TEST_F(HostileInputTest, FourHundredThousandTermsStayOutOfTheSpirvLeg) {
  std::string chain = "void mainImage(out vec4 c, in vec2 p) {\n  float a = p.x;\n  c = vec4(a";
  for (int i = 0; i < 400'000; ++i) chain += "+a";
  project_.Write("chain.frag", chain + ");\n}\n");
  Expect({{"port", "--emit", "spirv", "-o", "chain.spv", "chain.frag"}}, "[spirv/tree-too-deep]");
  const BoundedRun render =
      Run({"render", "chain.frag", "-o", "chain.png", "--hermetic", "--browser-optimiser"});
  EXPECT_FALSE(render.timed_out);
  EXPECT_LT(render.exit_code, 3) << render.Printed();
}

TEST_F(HostileInputTest, TenThousandNestedIfs) {
  std::string text;
  for (int i = 0; i < 10000; ++i) text += "#if 1\n";
  text += "void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n";
  for (int i = 0; i < 10000; ++i) text += "#endif\n";
  project_.Write("ifs.frag", text);
  Expect({{"check", "ifs.frag"}}, "ifs.frag:201:1: error: #if groups nested more than 200 deep");
  Expect({{"check", "ifs.frag"}}, "[preprocessor/conditional-too-deep]");
  // fix and port stop where check stops: glslang never sees the text.
  Expect({{"fix", "--diff", "ifs.frag"}, {"port", "-o", "ported.frag", "ifs.frag"}},
         "[preprocessor/conditional-too-deep]");
  EXPECT_FALSE(project_.Exists("ported.frag"));
}

TEST_F(HostileInputTest, ExponentialMacroUnderFixAndPort) {
  std::string text;
  for (int i = 0; i < 40; ++i) {
    text += "#define M" + std::to_string(i) + " M" + std::to_string(i + 1) + " M" +
            std::to_string(i + 1) + "\n";
  }
  project_.Write("macro.frag", text + "void mainImage(out vec4 c, in vec2 p) { c = vec4(M0); }\n");
  Expect({{"check", "macro.frag"}}, "macro.frag:41:");
  Expect({{"check", "macro.frag"}}, "[preprocessor/expansion-too-large]");
  Expect({{"fix", "--diff", "macro.frag"}, {"port", "-o", "ported.frag", "macro.frag"}},
         "macro.frag:");
}

TEST_F(HostileInputTest, SelfAndMutuallyReferentialMacrosStop) {
  project_.Write("recursive.frag",
                 "#define A A + 1.0\n#define B C\n#define C B\n"
                 "void mainImage(out vec4 c, in vec2 p) {\n  float x = A;\n  float y = B;\n"
                 "  c = vec4(x, y, 0.0, 1.0);\n}\n");
  Expect(CheckFixPort("recursive.frag"),
         "recursive.frag:5:13: error: 'A': undeclared identifier [glslang/undeclared-identifier]");
  Expect({{"check", "recursive.frag"}}, "recursive.frag:6:13: error: 'B': undeclared identifier");
}

TEST_F(HostileInputTest, DirectoryNamedAsAFile) {
  fs::create_directories(project_.Root() / "dir.frag");
  project_.Write("dir.frag/inner.frag", PassWithErrorOnLine3("\n"));
  // check, fix and port walk a directory argument, whatever its name.
  Expect({{"check", "dir.frag"}}, "dir.frag/inner.frag:3:13: error");
  Expect({{"render", "dir.frag", "--hermetic"}},
         "dir.frag:1:1: error: not a regular file: a directory [input/unreadable]");
  Expect({{"check", "--common", "dir.frag", "dir.frag/inner.frag"}},
         "--common dir.frag: not a regular file: a directory", 2);
}

// A FIFO with no writer: opening it for reading would wait forever.
TEST_F(HostileInputTest, FifoNamedAsAFileDoesNotBlock) {
  ASSERT_EQ(::mkfifo((project_.Root() / "pipe.frag").c_str(), 0644), 0);
  project_.Write("ok.frag",
                 "void mainImage(out vec4 c, in vec2 p) { c = vec4(p / 64.0, 0, 1); }\n");
  Expect(CheckFixPort("pipe.frag"), "pipe.frag:1:1: error: not a regular file: a FIFO");
  Expect({{"check", "pipe.frag"}, {"render", "pipe.frag", "--hermetic"}}, "[input/unreadable]");
  Expect({{"render", "ok.frag", "--channel0", "pipe.frag", "--hermetic"}},
         "cannot read pipe.frag: not a regular file [render/channel-image]");
  Expect({{"check", "--common", "pipe.frag", "ok.frag"}}, "--common pipe.frag: not a regular file",
         2);
}

// A walked FIFO is not a regular file and is not picked up at all.
TEST_F(HostileInputTest, FifoInsideAWalkedDirectoryIsSkipped) {
  ASSERT_EQ(::mkfifo((project_.Root() / "pipe.frag").c_str(), 0644), 0);
  project_.Write("sub/a.frag", PassWithErrorOnLine3("\n"));
  Expect({{"check", "."}}, "sub/a.frag:3:13: error");
}

// std::filesystem threw out of the walk (exit 3) at the first looping link.
TEST_F(HostileInputTest, SymlinkLoopsInsideAWalkedDirectory) {
  project_.Write("tree/a.frag", PassWithErrorOnLine3("\n"));
  fs::create_symlink("loop2.frag", project_.Root() / "tree/loop1.frag");
  fs::create_symlink("loop1.frag", project_.Root() / "tree/loop2.frag");
  fs::create_directories(project_.Root() / "tree/sub");
  fs::create_symlink("..", project_.Root() / "tree/sub/up");
  fs::create_symlink("../sub", project_.Root() / "tree/sub/self.frag");
  for (const std::string command : {"check", "fix", "port"}) {
    std::vector<std::string> args = {command, "tree"};
    if (command == "port") args = {"port", "--out-dir", "out", "tree"};
    const BoundedRun run = Run(args);
    EXPECT_EQ(run.exit_code, 2) << command << "\n" << run.Printed();
    EXPECT_NE(run.err.find("tree/loop1.frag: Too many levels of symbolic links"), std::string::npos)
        << command << "\n"
        << run.err;
    EXPECT_LT(run.seconds, kMaxSeconds);
  }
  // The other files are still checked, each once: the link to the parent is not followed.
  const BoundedRun run = Run({"check", "tree"});
  EXPECT_NE(run.out.find("tree/a.frag:3:13: error"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("in 1 file (1 file checked)"), std::string::npos) << run.out;
}

TEST_F(HostileInputTest, NamedSymlinkLoopSaysSo) {
  fs::create_symlink("loop.frag", project_.Root() / "loop.frag");
  Expect({{"check", "loop.frag"}}, "loop.frag: Too many levels of symbolic links", 2);
}

// Root reads a mode-000 file anyway: the child then runs as nobody (setpriv).
TEST_F(HostileInputTest, UnreadableFileAndDirectory) {
  if (RunningAsRoot() && !fs::exists("/usr/bin/setpriv")) GTEST_SKIP() << "needs setpriv as root";
  fs::permissions(project_.Root(), fs::perms::owner_all | fs::perms::others_read |
                                       fs::perms::others_exec | fs::perms::group_read |
                                       fs::perms::group_exec);
  project_.Write("locked.frag", PassWithErrorOnLine3("\n"));
  project_.Write("tree/ok.frag", PassWithErrorOnLine3("\n"));
  project_.Write("tree/closed/hidden.frag", PassWithErrorOnLine3("\n"));
  fs::permissions(project_.Root() / "locked.frag", fs::perms::none);
  fs::permissions(project_.Root() / "tree/closed", fs::perms::none);
  BoundedRunOptions nobody;
  nobody.unprivileged = true;
  const BoundedRun file = Run({"check", "--no-cache", "locked.frag"}, nobody);
  EXPECT_EQ(file.exit_code, 1) << file.Printed();
  EXPECT_NE(file.out.find("locked.frag:1:1: error: cannot open file: Permission denied "
                          "[input/unreadable]"),
            std::string::npos)
      << file.Printed();
  const BoundedRun tree = Run({"check", "--no-cache", "tree"}, nobody);
  EXPECT_EQ(tree.exit_code, 2) << tree.Printed();
  EXPECT_NE(tree.out.find("tree/ok.frag:3:13: error"), std::string::npos) << tree.Printed();
  EXPECT_NE(tree.err.find("tree/closed: directory not readable, its files are not checked"),
            std::string::npos)
      << tree.Printed();
  fs::permissions(project_.Root() / "tree/closed", fs::perms::owner_all);
}

}  // namespace
}  // namespace shaderport::testing
