#include "rule/fix_engine.h"

#include <gtest/gtest.h>

#include "rule/fix_selection.h"
#include "test_rules.h"

namespace shaderport::rule {
namespace {

using testing::FlagRule;
using testing::RenameRule;

FixEngineResult RunEngine(const std::string& text, std::vector<const Rule*> rules,
                          int max_rounds = FixEngineOptions{}.max_rounds) {
  const SourceFile file(0, "test.frag", text);
  FixEngineOptions options;
  options.rules = std::move(rules);
  options.max_rounds = max_rounds;
  return RunFixEngine(file, options);
}

bool HasNote(const Diagnostic& d, std::string_view part) {
  for (const auto& note : d.notes) {
    if (note.message.find(part) != std::string::npos) return true;
  }
  return false;
}

TEST(FixEngine, AppliesFixesAndStopsWhenNothingChanges) {
  const RenameRule rename("test/rename", "foo", "bar");
  const auto result = RunEngine("float foo; void main() { foo = 1.0; }", {&rename});
  EXPECT_EQ(result.text, "float bar; void main() { bar = 1.0; }");
  EXPECT_EQ(result.rounds, 1);
  EXPECT_TRUE(result.converged);
  EXPECT_EQ(result.fixed.size(), 2u);
  EXPECT_TRUE(result.remaining.empty());
}

TEST(FixEngine, ChainsRoundsAndMapsLaterFindingsToTheOriginal) {
  // Round 1: aaa -> bbb; round 2: bbb -> cc; then the flag rule sees cc.
  const RenameRule first("test/a", "aaa", "bbb");
  const RenameRule second("test/b", "bbb", "cc");
  const FlagRule flag("cc");
  const std::string original = "float x;\nfloat aaa;";
  const auto result = RunEngine(original, {&first, &second, &flag});
  EXPECT_EQ(result.text, "float x;\nfloat cc;");
  EXPECT_EQ(result.rounds, 2);
  ASSERT_EQ(result.remaining.size(), 1u);
  EXPECT_EQ(result.remaining[0].rule_id, "test/flag");
  EXPECT_EQ(result.remaining[0].range.begin, original.find("aaa"));
  EXPECT_EQ(result.remaining[0].range.end, original.find("aaa") + 3);
  EXPECT_EQ(result.map.ToOriginal(static_cast<uint32_t>(result.text.find("cc"))),
            original.find("aaa"));
}

const Diagnostic* InternalError(const FixEngineResult& result) {
  for (const auto& d : result.remaining) {
    if (d.rule_id == "internal/error") return &d;
  }
  return nullptr;
}

// x -> y -> x: once the bystander's one-off rename is done, the text comes back
// every two rounds; more rounds would not help, and the bystander is not blamed.
TEST(FixEngine, RulesThatUndoEachOtherStopWhenTheTextComesBack) {
  const RenameRule there("test/there", "x", "y");
  const RenameRule back("test/back", "y", "x");
  const RenameRule bystander("test/bystander", "zzz", "w");
  const auto result = RunEngine("float x; float zzz;", {&there, &back, &bystander});
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.rounds, 3);
  const Diagnostic* internal = InternalError(result);
  ASSERT_NE(internal, nullptr);
  EXPECT_EQ(internal->message,
            "rules undo each other's fixes (the text came back to what it was 2 rounds "
            "earlier): test/back, test/there");
}

// Six renames that each wait for the previous one: with the old limit of three
// rounds this converging chain was reported as rules fighting.
TEST(FixEngine, ChainsLongerThanThreeRoundsConverge) {
  const RenameRule r1("test/1", "a1", "a2"), r2("test/2", "a2", "a3"), r3("test/3", "a3", "a4"),
      r4("test/4", "a4", "a5"), r5("test/5", "a5", "a6"), r6("test/6", "a6", "a7");
  const auto result = RunEngine("float a1;", {&r6, &r5, &r4, &r3, &r2, &r1});
  EXPECT_TRUE(result.converged);
  EXPECT_EQ(result.text, "float a7;");
  EXPECT_EQ(result.rounds, 6);
  EXPECT_EQ(InternalError(result), nullptr);

  const auto capped = RunEngine("float a1;", {&r6, &r5, &r4, &r3, &r2, &r1}, 3);
  EXPECT_FALSE(capped.converged);
  EXPECT_EQ(capped.text, "float a4;");
  const Diagnostic* internal = InternalError(capped);
  ASSERT_NE(internal, nullptr);
  EXPECT_EQ(internal->message,
            "rules still wanted changes after 3 rounds: test/1, test/2, test/3, test/4");
}

TEST(FixEngine, UnterminatedMacroDoesNotCrash) {
  const RenameRule rename("test/rename", "foo", "bar");
  const auto result = RunEngine("#define foo(\nfoo(", {&rename});
  EXPECT_TRUE(result.converged);
}

TEST(FixEngine, IsIdempotent) {
  const RenameRule first("test/a", "aaa", "bbb");
  const RenameRule second("test/b", "bbb", "cc");
  const auto once = RunEngine("float aaa; float bbb; // aaa\n", {&first, &second});
  const auto twice = RunEngine(once.text, {&first, &second});
  EXPECT_EQ(twice.text, once.text);
  EXPECT_EQ(twice.rounds, 0);
}

TEST(FixEngine, OverlappingFixesEarlierRuleWins) {
  const RenameRule winner("test/a-first", "foo", "bar");
  const RenameRule loser("test/b-second", "foo", "baz");
  const auto result = RunEngine("float foo;", {&winner, &loser});
  EXPECT_EQ(result.text, "float bar;");
}

TEST(FixSelection, LoserGetsANoteAndDuplicatesMerge) {
  DiagnosticList list;
  list.push_back({Severity::kWarning, "test/a", {0, 0, 3}, "a", {}, {{{0, 0, 3}, "X"}}});
  list.push_back({Severity::kWarning, "test/b", {0, 1, 2}, "b", {}, {{{0, 1, 2}, "Y"}}});
  list.push_back({Severity::kWarning, "test/c", {0, 0, 3}, "c", {}, {{{0, 0, 3}, "X"}}});
  list.push_back({Severity::kWarning,
                  "test/d",
                  {0, 5, 6},
                  "d",
                  {},
                  {{{0, 5, 6}, "Z", FixSafety::kSuggestion}}});
  list.push_back({Severity::kWarning, "test/e", {1, 5, 6}, "other file", {}, {{{1, 5, 6}, "Z"}}});
  FixSelectionOptions options;
  options.file = 0;
  const FixSelection selection = SelectFixes(list, options);
  ASSERT_EQ(selection.edits.size(), 1u);
  EXPECT_EQ(selection.edits[0].text, "X");
  EXPECT_EQ(selection.applied, (std::vector<size_t>{0, 2}));
  EXPECT_TRUE(HasNote(list[1], "test/a"));
  EXPECT_TRUE(list[3].notes.empty());  // suggestions are shown, not applied, not noted
}

TEST(FixSelection, RefusedFixesGetTheNote) {
  DiagnosticList list;
  list.push_back({Severity::kWarning, "test/a", {0, 0, 3}, "a", {}, {{{0, 0, 3}, "X"}}});
  FixSelectionOptions options;
  options.file = 0;
  options.allow = [](const Diagnostic&) { return false; };
  options.refused_note = "not applied: the result did not validate";
  EXPECT_TRUE(SelectFixes(list, options).edits.empty());
  EXPECT_TRUE(HasNote(list[0], "did not validate"));
}

TEST(MacroFixes, BodyEditAppliesWhenEveryExpansionAgrees) {
  const RenameRule rename("test/rename", "foo", "bar");
  const auto result = RunEngine("#define ONE foo\nfloat a = ONE;\nfloat b = ONE;\n", {&rename});
  EXPECT_EQ(result.text, "#define ONE bar\nfloat a = ONE;\nfloat b = ONE;\n");
}

TEST(MacroFixes, BodyEditIsRefusedWhenExpansionsDisagree) {
  const RenameRule rename("test/rename", "foo", "bar", /*only_line=*/2);
  const std::string text = "#define ONE foo\nfloat a = ONE;\nfloat b = ONE;\n";
  const auto result = RunEngine(text, {&rename});
  EXPECT_EQ(result.text, text);
  ASSERT_EQ(result.remaining.size(), 1u);
  EXPECT_TRUE(result.remaining[0].fixes.empty());
  EXPECT_TRUE(HasNote(result.remaining[0], "macro 'ONE'"));
}

TEST(MacroFixes, EditsOfMacroArgumentsAreNotApplied) {
  const RenameRule rename("test/rename", "foo", "bar");
  const std::string text = "#define ID(x) x\nfloat foo;\nfloat a = ID(foo);\n";
  const auto result = RunEngine(text, {&rename});
  EXPECT_EQ(result.text, "#define ID(x) x\nfloat bar;\nfloat a = ID(foo);\n");
  ASSERT_EQ(result.remaining.size(), 1u);
  EXPECT_TRUE(HasNote(result.remaining[0], "inside macro 'ID'"));
}

TEST(FixEngine, BrokenInputDoesNotCrash) {
  const RenameRule rename("test/rename", "foo", "bar");
  for (const char* text : {"", "foo", "void main( { foo", "\x01\xff foo"}) {
    const auto result = RunEngine(text, {&rename});
    EXPECT_EQ(result.text.find("foo"), std::string::npos) << text;
    EXPECT_TRUE(result.converged);
  }
}

// 10,100 nested parentheses: past the parser's limit no rule runs and the text is kept.
TEST(FixEngine, TextPastALimitIsNotRewritten) {
  const RenameRule rename("test/rename", "foo", "bar");
  const std::string text =
      "float foo;\nfloat y = " + std::string(10100, '(') + "1.0" + std::string(10100, ')') + ";\n";
  const auto result = RunEngine(text, {&rename});
  EXPECT_TRUE(result.limit_breached);
  EXPECT_TRUE(result.converged);
  EXPECT_EQ(result.text, text);
  EXPECT_TRUE(result.fixed.empty());
  ASSERT_EQ(result.front_end.size(), 1u);
  EXPECT_EQ(result.front_end[0].rule_id, "syntax/nesting-too-deep");
}

// A fix that nests the text past the limit: the engine stops, unconverged, naming it.
TEST(FixEngine, FixesThatPushTheTextPastALimitDoNotConverge) {
  const RenameRule deepen("test/deepen", "foo",
                          std::string(10100, '(') + "1.0" + std::string(10100, ')'));
  const auto result = RunEngine("float y = foo;\n", {&deepen});
  EXPECT_TRUE(result.limit_breached);
  EXPECT_FALSE(result.converged);
  const Diagnostic* internal = InternalError(result);
  ASSERT_NE(internal, nullptr);
  EXPECT_EQ(internal->message,
            "fixes made the text exceed a resource limit (docs/limits.md): test/deepen");
}

}  // namespace
}  // namespace shaderport::rule
