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

// With deferred checks a burst of changes is checked once, as its last version, and
// a request first publishes what is pending.
TEST(LspSession, DeferredChecksRunOnceForTheLastVersion) {
  LspSession session({"test", {}, true});
  session.Handle({{"jsonrpc", "2.0"}, {"id", 1}, {"method", "initialize"}});
  const nlohmann::json open = {
      {"jsonrpc", "2.0"},
      {"method", "textDocument/didOpen"},
      {"params",
       {{"textDocument",
         {{"uri", "file:///tmp/deferred.frag"}, {"version", 1}, {"text", "void main() {}\n"}}}}}};
  EXPECT_TRUE(session.Handle(open).empty());
  for (int version = 2; version <= 4; ++version) {
    EXPECT_TRUE(session
                    .Handle({{"jsonrpc", "2.0"},
                             {"method", "textDocument/didChange"},
                             {"params",
                              {{"textDocument",
                                {{"uri", "file:///tmp/deferred.frag"}, {"version", version}}},
                               {"contentChanges", {{{"text", "void main() { x; }\n"}}}}}}})
                    .empty());
  }
  // The first check also tells what the verdict is against (window/logMessage).
  const auto flushed = session.Flush();
  ASSERT_EQ(flushed.size(), 2u);
  EXPECT_EQ(flushed[0]["method"], "window/logMessage");
  EXPECT_EQ(flushed[0]["params"]["message"],
            "deferred.frag is checked as a webgl1 fragment shader, target webgl1");
  EXPECT_EQ(flushed[1]["params"]["version"], 4);
  EXPECT_FALSE(flushed[1]["params"]["diagnostics"].empty());
  EXPECT_TRUE(session.Flush().empty());
  session.Handle({{"jsonrpc", "2.0"},
                  {"method", "textDocument/didChange"},
                  {"params",
                   {{"textDocument", {{"uri", "file:///tmp/deferred.frag"}, {"version", 5}}},
                    {"contentChanges", {{{"text", "void main() {}\n"}}}}}}});
  const auto answered = session.Handle({{"jsonrpc", "2.0"},
                                        {"id", 2},
                                        {"method", "textDocument/codeAction"},
                                        {"params",
                                         {{"textDocument", {{"uri", "file:///tmp/deferred.frag"}}},
                                          {"range",
                                           {{"start", {{"line", 0}, {"character", 0}}},
                                            {"end", {{"line", 0}, {"character", 1}}}}}}}});
  ASSERT_EQ(answered.size(), 2u);
  EXPECT_EQ(answered[0]["method"], "textDocument/publishDiagnostics");
  EXPECT_EQ(answered[0]["params"]["version"], 5);
  EXPECT_EQ(answered[1]["id"], 2);
}

}  // namespace
}  // namespace shaderport::driver::lsp
