#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "driver/suppress/suppression_comment.h"
#include "driver/suppress/suppressions.h"
#include "glsl/lex/lexer.h"
#include "source/source_manager.h"

namespace shaderport::driver {
namespace {

TEST(SuppressionComment, Forms) {
  EXPECT_FALSE(ParseSuppressionComment("// just a comment").has_value());
  EXPECT_FALSE(ParseSuppressionComment("// TODO shaderport-ignore(input/empty)").has_value());

  auto all = ParseSuppressionComment("// shaderport-ignore");
  ASSERT_TRUE(all);
  EXPECT_TRUE(all->error.empty());
  EXPECT_TRUE(all->patterns.empty());
  EXPECT_FALSE(all->next_line);

  auto two = ParseSuppressionComment("//shaderport-ignore( input/empty ,input/* ) because");
  ASSERT_TRUE(two);
  EXPECT_TRUE(two->error.empty()) << two->error;
  ASSERT_EQ(two->patterns.size(), 2u);
  EXPECT_EQ(two->patterns[0].pattern, "input/empty");
  EXPECT_EQ(two->patterns[0].offset, 21u);
  EXPECT_EQ(two->patterns[1].pattern, "input/*");

  auto next = ParseSuppressionComment("/* shaderport-ignore-next-line(input/empty) */");
  ASSERT_TRUE(next);
  EXPECT_TRUE(next->next_line);
  EXPECT_EQ(next->patterns.size(), 1u);
}

TEST(SuppressionComment, MalformedOnes) {
  for (const char* text :
       {"// shaderport-ignore()", "// shaderport-ignore(input/empty", "// shaderport-ignore(a,)",
        "// shaderport-ignore(Input/Empty)", "// shaderport-ignore(x)", "// shaderport-ignored",
        "// shaderport-ignore-line(input/empty)", "/* shaderport-ignore(input/empty */)"}) {
    auto directive = ParseSuppressionComment(text);
    ASSERT_TRUE(directive) << text;
    EXPECT_FALSE(directive->error.empty()) << text;
  }
}

// A lexed file and diagnostics placed with At(line, rule).
struct Fixture {
  SourceManager sources;
  const SourceFile* file;
  glsl::LexedFile lexed;
  DiagnosticList diagnostics;

  explicit Fixture(std::string text) {
    file = &sources.Add("t.frag", std::move(text));
    lexed = glsl::Lex(*file);
  }
  void At(uint32_t line, std::string rule) {
    Diagnostic d;
    d.rule_id = std::move(rule);
    const uint32_t start = file->LineStart(line);
    d.range = {file->Id(), start, start + 1};
    d.message = "m";
    diagnostics.push_back(std::move(d));
  }
  // "line rule" of what is left, in order.
  std::vector<std::string> Left() const {
    std::vector<std::string> out;
    for (const Diagnostic& d : diagnostics) {
      out.push_back(std::to_string(file->LocationOf(d.range.begin).line) + " " + d.rule_id);
    }
    return out;
  }
};

using Lines = std::vector<std::string>;

TEST(Suppressions, SameLineAndNextLine) {
  Fixture f(
      "float a = 1.0; // shaderport-ignore(input/empty)\n"
      "// shaderport-ignore-next-line(input/binary, input/empty)\n"
      "float b = 2.0;\n"
      "float c = 3.0;\n");
  f.At(1, "input/empty");
  f.At(1, "input/binary");  // not named: kept
  f.At(3, "input/binary");
  f.At(3, "input/empty");
  f.At(4, "input/empty");  // the next-line comment covers line 3 only
  ApplySuppressions(*f.file, f.lexed, f.diagnostics);
  EXPECT_EQ(f.Left(), (Lines{"1 input/binary", "4 input/empty"}));
}

TEST(Suppressions, WildcardsAndNoList) {
  Fixture f("x; // shaderport-ignore(input/*)\ny; // shaderport-ignore\n");
  f.At(1, "input/empty");
  f.At(1, "input/binary");
  f.At(1, "internal/error");
  f.At(2, "internal/error");
  f.At(2, "input/empty");
  ApplySuppressions(*f.file, f.lexed, f.diagnostics);
  EXPECT_EQ(f.Left(), (Lines{"1 internal/error"}));
}

TEST(Suppressions, UnusedOnesAreReportedAtTheRuleId) {
  Fixture f("x; // shaderport-ignore(input/empty, input/binary)\ny; // shaderport-ignore\n");
  f.At(1, "input/empty");
  ApplySuppressions(*f.file, f.lexed, f.diagnostics);
  ASSERT_EQ(f.Left(), (Lines{"1 suppression/unused", "2 suppression/unused"}));
  const Diagnostic& unused = f.diagnostics[0];
  EXPECT_EQ(unused.severity, Severity::kWarning);
  EXPECT_EQ(f.file->Text().substr(unused.range.begin, unused.range.Size()), "input/binary");
  EXPECT_TRUE(unused.fixes.empty());  // input/empty was used: the comment stays
  // Nothing used at all: offered for removal.
  ASSERT_EQ(f.diagnostics[1].fixes.size(), 1u);
  EXPECT_EQ(f.diagnostics[1].fixes[0].safety, FixSafety::kSuggestion);
  EXPECT_EQ(f.file->Text().substr(f.diagnostics[1].fixes[0].range.begin,
                                  f.diagnostics[1].fixes[0].range.Size()),
            "// shaderport-ignore");
}

TEST(Suppressions, UnusedReportingCanBeTurnedOff) {
  Fixture f("x; // shaderport-ignore(input/empty)\n");
  ApplySuppressions(*f.file, f.lexed, f.diagnostics, {}, {.report_unused = false});
  EXPECT_TRUE(f.diagnostics.empty());
}

TEST(Suppressions, MalformedAndUnknownRulesAreReported) {
  Fixture f("x; // shaderport-ignore(input/empty\ny; // shaderport-ignore(nosuch/rule)\n");
  f.At(1, "input/empty");
  ApplySuppressions(*f.file, f.lexed, f.diagnostics);
  EXPECT_EQ(f.Left(),
            (Lines{"1 input/empty", "1 suppression/malformed", "2 suppression/unknown-rule"}));
}

TEST(Suppressions, OnlyRealActiveCommentsCount) {
  Fixture f(
      "#if 0\n"
      "x; // shaderport-ignore(input/empty)\n"
      "#endif\n"
      "/* a block comment that mentions // shaderport-ignore(input/empty) */ y;\n"
      "#define Q /* shaderport-ignore(input/binary) */ 1\n");
  f.At(2, "input/empty");
  f.At(4, "input/empty");
  f.At(5, "input/binary");
  // The preprocessor would report line 2 as inactive.
  const SourceRange inactive{f.file->Id(), f.file->LineStart(2), f.file->LineStart(3)};
  ApplySuppressions(*f.file, f.lexed, f.diagnostics, std::span(&inactive, 1));
  EXPECT_EQ(f.Left(), (Lines{"2 input/empty", "4 input/empty"}));
}

TEST(Suppressions, OtherFilesAndOwnDiagnosticsAreLeftAlone) {
  Fixture f("x; // shaderport-ignore\n");
  const SourceFile& other = f.sources.Add("common.glsl", "y;\n");
  Diagnostic elsewhere;
  elsewhere.rule_id = "input/empty";
  elsewhere.range = {other.Id(), 0, 1};
  f.diagnostics.push_back(elsewhere);
  f.At(1, "suppression/unused");
  Diagnostic whole_file;  // no range: cannot be on a suppressed line
  whole_file.rule_id = "input/empty";
  f.diagnostics.push_back(whole_file);
  ApplySuppressions(*f.file, f.lexed, f.diagnostics);
  // The "every rule" comment silenced nothing of its own file: unused.
  EXPECT_EQ(f.diagnostics.size(), 4u);
  EXPECT_EQ(f.diagnostics.back().rule_id, "suppression/unused");
}

TEST(Suppressions, ContinuedLineComment) {
  Fixture f("x; // shaderport-ignore-next-line(input/empty) \\\n still comment\ny;\n");
  f.At(3, "input/empty");
  ApplySuppressions(*f.file, f.lexed, f.diagnostics);
  EXPECT_TRUE(f.diagnostics.empty()) << f.Left().front();
}

}  // namespace
}  // namespace shaderport::driver
