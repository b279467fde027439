// Hostile input through the real binary: each case gets one clear diagnostic and
// a non-zero exit, never a crash, a hang or unbounded memory.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli_test_util.h"

namespace shaderport::testing {
namespace {

namespace fs = std::filesystem;

class BadInputTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("shaderport-bad-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  void Write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
  }

  // Runs `command` (check or dump --ast) on `name` under a time limit.
  CommandResult Run(const std::string& command, const std::string& name) {
    return RunShaderport(command + " " + name, dir_);
  }

  // `check` reports glslang's verdict, `dump` our front end's: each names the
  // problem with its own rule id (`check_rule` defaults to `rule`).
  void ExpectOneDiagnostic(const std::string& name, const std::string& rule,
                           std::string check_rule = "") {
    if (check_rule.empty()) check_rule = rule;
    for (const std::string command : {"check", "dump --ast"}) {
      const std::string& expected = command == "check" ? check_rule : rule;
      const CommandResult result = Run(command, name);
      const std::string& printed = command == "check" ? result.out : result.err;
      EXPECT_EQ(result.exit_code, 1) << command << " " << name << "\n" << printed;
      EXPECT_NE(printed.find("[" + expected + "]"), std::string::npos)
          << command << " " << name << "\n"
          << printed.substr(0, 2000);
    }
  }

  fs::path dir_;
};

TEST_F(BadInputTest, EmptyFile) {
  Write("empty.frag", "");
  ExpectOneDiagnostic("empty.frag", "input/empty");
}

TEST_F(BadInputTest, BinaryFile) {
  std::string bytes;
  for (int i = 0; i < 4096; ++i) bytes.push_back(static_cast<char>((i * 7919) & 0xff));
  Write("blob.frag", bytes);
  ExpectOneDiagnostic("blob.frag", "input/binary");
}

TEST_F(BadInputTest, FiftyMegabyteFileIsRejectedBeforeReading) {
  {
    std::ofstream out(dir_ / "huge.frag", std::ios::binary);
    out.seekp(50 << 20);
    out.put('\n');
  }
  ExpectOneDiagnostic("huge.frag", "input/too-large");
}

TEST_F(BadInputTest, HundredThousandNestedParentheses) {
  Write("parens.frag", "void main() { float x = " + std::string(100000, '(') + "1.0" +
                           std::string(100000, ')') + "; }\n");
  ExpectOneDiagnostic("parens.frag", "syntax/nesting-too-deep");
}

TEST_F(BadInputTest, ExponentialMacro) {
  std::string text;
  for (int i = 0; i < 40; ++i) {
    text += "#define M" + std::to_string(i) + " M" + std::to_string(i + 1) + " M" +
            std::to_string(i + 1) + "\n";
  }
  text += "void main() { float x = M0; }\n";
  Write("macro.frag", text);
  ExpectOneDiagnostic("macro.frag", "preprocessor/expansion-too-large");
}

TEST_F(BadInputTest, UnterminatedComment) {
  Write("comment.frag", "void main() { }\n/* never closed\n");
  ExpectOneDiagnostic("comment.frag", "lex/unterminated-comment", "glslang/unterminated-comment");
}

}  // namespace
}  // namespace shaderport::testing
