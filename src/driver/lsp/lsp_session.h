// A Language Server Protocol session (LSP 3.17): the messages of one client in, the
// messages to send out. Open documents are checked as `shaderport check` checks a
// file given on standard input under the document's path (its .shaderport.toml and
// Common apply), so the editor shows the same findings, ids and severities. Fix-its
// become quick fixes; `source.fixAll.shaderport` is what `shaderport fix` writes.
// The session does no I/O: the CLI frames the messages (shaderport lsp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "driver/dialect.h"

namespace shaderport::driver::lsp {

struct SessionOptions {
  std::string tool_version;
  std::vector<std::string> rules_with_sections;  // sorted: rules with a docs section
  // Changes only mark a document; Flush() checks each marked one once. The server
  // flushes when no message is waiting, so a burst of keystrokes is checked once, as
  // its last version (stale versions are never checked).
  bool defer_checks = false;
};

class LspSession {
 public:
  explicit LspSession(SessionOptions options) : options_(std::move(options)) {}

  // One parsed message; returns the responses and notifications to send, in order.
  std::vector<nlohmann::json> Handle(const nlohmann::json& message);

  // Checks and publishes every document changed since the last flush (defer_checks).
  std::vector<nlohmann::json> Flush();

  // The response to a message that was not JSON (JSON-RPC's parse error, id null).
  static nlohmann::json ParseErrorResponse(std::string_view what);

  bool Exited() const { return exited_; }
  // After `exit`: 0 when `shutdown` came first, else 1 (as the protocol says).
  int ExitCode() const { return shutdown_ ? 0 : 1; }

 private:
  struct Published {
    nlohmann::json diagnostic;  // as sent in publishDiagnostics
    nlohmann::json edits;       // its fix-its as TextEdits (an array; empty: none)
    bool safe = false;          // every fix-it safe: `shaderport fix` applies them
  };
  struct Document {
    std::filesystem::path path;
    std::string text;
    int64_t version = 0;
    std::vector<Published> published;
    std::string decision;  // last told to the client (window/logMessage)
  };

  nlohmann::json Dispatch(const std::string& method, const nlohmann::json& params,
                          std::vector<nlohmann::json>& out);
  void Publish(const std::string& uri, Document& document, std::vector<nlohmann::json>& out);
  void Changed(const std::string& uri, Document& document, std::vector<nlohmann::json>& out);
  nlohmann::json CodeActions(const nlohmann::json& params);

  SessionOptions options_;
  std::map<std::string, Document> documents_;  // by URI
  std::vector<std::string> dirty_;             // changed, not yet checked (defer_checks)
  // From workspace/didChangeConfiguration, `shaderport.target`: the WebGL context every
  // document is checked for (unset: decided per file, as check does).
  std::optional<model::Target> target_;
  bool initialized_ = false;
  bool shutdown_ = false;
  bool exited_ = false;
};

// The file a URI names: file:///a%20b/x.glsl -> /a b/x.glsl; any other scheme keeps
// its path part (untitled:Untitled-1 -> Untitled-1), so the extension still counts.
std::filesystem::path PathOfUri(std::string_view uri);

}  // namespace shaderport::driver::lsp
