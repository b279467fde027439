// LSP positions count UTF-16 code units; shaderport counts bytes. Conversions both
// ways, past-the-end clamping as the protocol asks, and the client's edits.
#include "driver/lsp/lsp_text.h"

#include <gtest/gtest.h>

#include "driver/lsp/lsp_session.h"

namespace shaderport::driver::lsp {
namespace {

TEST(LspText, PositionsCountUtf16CodeUnits) {
  // 'é' is 2 bytes and 1 unit; U+1F600 is 4 bytes and 2 units (a surrogate pair).
  const std::string text = "a\n\xC3\xA9x\xF0\x9F\x98\x80y\n";
  EXPECT_EQ(PositionOf(text, 0).line, 0u);
  const Position x = PositionOf(text, 4);  // after 'é'
  EXPECT_EQ(x.line, 1u);
  EXPECT_EQ(x.character, 1u);
  const Position y = PositionOf(text, 9);  // after the emoji
  EXPECT_EQ(y.character, 4u);
  EXPECT_EQ(OffsetOf(text, {1, 1}), 4u);
  EXPECT_EQ(OffsetOf(text, {1, 4}), 9u);
  // Past the line's end: the line's end; past the last line: the text's end.
  EXPECT_EQ(OffsetOf(text, {0, 40}), 1u);
  EXPECT_EQ(OffsetOf(text, {9, 0}), text.size());
}

TEST(LspText, ChangesReplaceRangesOrEverything) {
  std::string text = "float t = iGlobalTime;\n";
  ASSERT_TRUE(ApplyChange(text, {{"range",
                                  {{"start", {{"line", 0}, {"character", 10}}},
                                   {"end", {{"line", 0}, {"character", 21}}}}},
                                 {"text", "iTime"}}));
  EXPECT_EQ(text, "float t = iTime;\n");
  ASSERT_TRUE(ApplyChange(text, {{"text", "void main() {}\n"}}));
  EXPECT_EQ(text, "void main() {}\n");
  EXPECT_FALSE(ApplyChange(text, {{"range", 3}, {"text", "x"}}));
  EXPECT_FALSE(ApplyChange(text, {{"range",
                                   {{"start", {{"line", -1}, {"character", 0}}},
                                    {"end", {{"line", 0}, {"character", 0}}}}},
                                  {"text", "x"}}));
  EXPECT_EQ(text, "void main() {}\n");
}

TEST(LspText, UrisNameFiles) {
  EXPECT_EQ(PathOfUri("file:///a%20b/x.glsl"), "/a b/x.glsl");
  EXPECT_EQ(PathOfUri("untitled:Untitled-1.frag"), "Untitled-1.frag");
}

TEST(LspSession, AnswersEveryRequestOnceAndKnowsItsErrors) {
  LspSession session({"test", {}});
  const auto before = session.Handle({{"jsonrpc", "2.0"}, {"id", 1}, {"method", "shutdown"}});
  ASSERT_EQ(before.size(), 1u);
  EXPECT_EQ(before[0]["error"]["code"], -32002);
  const auto init = session.Handle({{"jsonrpc", "2.0"}, {"id", 2}, {"method", "initialize"}});
  ASSERT_EQ(init.size(), 1u);
  EXPECT_EQ(init[0]["result"]["capabilities"]["textDocumentSync"]["change"], 2);
  const auto bad = session.Handle({{"jsonrpc", "2.0"},
                                   {"id", 3},
                                   {"method", "textDocument/codeAction"},
                                   {"params", {{"textDocument", 7}}}});
  ASSERT_EQ(bad.size(), 1u);
  EXPECT_EQ(bad[0]["error"]["code"], -32602);
  EXPECT_TRUE(session.Handle({{"jsonrpc", "2.0"}, {"method", "unknown/notification"}}).empty());
  EXPECT_EQ(session.Handle(nlohmann::json::array())[0]["error"]["code"], -32600);
  session.Handle({{"jsonrpc", "2.0"}, {"method", "exit"}});
  EXPECT_TRUE(session.Exited());
  EXPECT_EQ(session.ExitCode(), 1);  // exit without shutdown
}

// With checks left to the caller (LspServer), a burst of changes is one job for its
// last version, and a job whose document changed while it ran publishes nothing.
TEST(LspSession, CallerChecksTakeTheLastVersionAndDropStaleResults) {
  LspSession session({"test", {}, true});
  session.Handle({{"jsonrpc", "2.0"}, {"id", 1}, {"method", "initialize"}});
  const std::string uri = "file:///tmp/deferred.frag";
  const auto change = [&](int version, const char* text) {
    return session.Handle({{"jsonrpc", "2.0"},
                           {"method", "textDocument/didChange"},
                           {"params",
                            {{"textDocument", {{"uri", uri}, {"version", version}}},
                             {"contentChanges", {{{"text", text}}}}}}});
  };
  EXPECT_TRUE(session
                  .Handle({{"jsonrpc", "2.0"},
                           {"method", "textDocument/didOpen"},
                           {"params",
                            {{"textDocument",
                              {{"uri", uri}, {"version", 1}, {"text", "void main() {}\n"}}}}}})
                  .empty());
  for (int version = 2; version <= 4; ++version)
    EXPECT_TRUE(change(version, "void main() { x; }\n").empty());
  std::optional<CheckJob> job = session.TakeCheck();
  ASSERT_TRUE(job.has_value());
  EXPECT_EQ(job->text, "void main() { x; }\n");
  EXPECT_FALSE(session.TakeCheck().has_value());
  // The first check also tells what the verdict is against (window/logMessage).
  const auto published = session.Completed(*job, job->Run({}));
  ASSERT_EQ(published.size(), 3u);
  EXPECT_EQ(published[0]["method"], "window/logMessage");
  EXPECT_EQ(published[0]["params"]["message"],
            "deferred.frag is checked as a webgl1 fragment shader, target webgl1");
  EXPECT_EQ(published[1]["method"], "shaderport/status");
  EXPECT_EQ(published[1]["params"]["target"], "webgl1");
  EXPECT_TRUE(published[1]["params"]["fails"].get<bool>());
  EXPECT_EQ(published[2]["params"]["version"], 4);
  EXPECT_FALSE(published[2]["params"]["diagnostics"].empty());

  change(5, "void main() {}\n");
  std::optional<CheckJob> stale = session.TakeCheck();
  ASSERT_TRUE(stale.has_value());
  change(6, "void main() { y; }\n");
  EXPECT_TRUE(session.Completed(*stale, stale->Run({})).empty());
  std::optional<CheckJob> fresh = session.TakeCheck();
  ASSERT_TRUE(fresh.has_value());
  EXPECT_EQ(fresh->text, "void main() { y; }\n");

  // Code actions are the caller's too: the session hands out what they need.
  const LspSession::CodeActionRequest request =
      session.TakeCodeActionRequest({{"jsonrpc", "2.0"},
                                     {"id", 2},
                                     {"method", "textDocument/codeAction"},
                                     {"params",
                                      {{"textDocument", {{"uri", uri}}},
                                       {"range",
                                        {{"start", {{"line", 0}, {"character", 0}}},
                                         {"end", {{"line", 0}, {"character", 1}}}}}}}});
  ASSERT_TRUE(request.input.has_value());
  EXPECT_EQ(request.input->text, "void main() { y; }\n");
}

}  // namespace
}  // namespace shaderport::driver::lsp
