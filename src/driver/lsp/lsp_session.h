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
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"
#include "driver/dialect.h"
#include "driver/lsp/lsp_check.h"
#include "driver/lsp/lsp_project.h"

namespace shaderport::driver::lsp {

struct SessionOptions {
  std::string tool_version;
  std::vector<std::string> rules_with_sections;  // sorted: rules with a docs section
  // Changes only mark a document; the caller takes each marked one with TakeCheck(),
  // checks it away from the session (CheckJob::Run) and hands the result to
  // Completed(), which publishes it unless the document changed meanwhile. A burst of
  // keystrokes is checked as its last version (LspServer does this on a worker).
  bool checks_by_caller = false;
};

// A document as it was when its check began: what a worker checks, without the session.
struct CheckJob {
  std::string uri;
  std::filesystem::path path;
  std::string text;
  uint64_t revision = 0;  // the document's revision then: a newer one makes the result stale
  DocumentCheckSettings settings;  // the client's settings then (render: a render-on-save)

  DocumentCheck Run(const std::vector<std::string>& rules_with_sections) const;
};

// What a code action request needs, taken from the session: computed off its lock.
struct CodeActionInput {
  std::string uri;
  std::filesystem::path path;
  std::string text;
  nlohmann::json range;
  std::vector<DocumentFinding> published;
};
nlohmann::json ComputeCodeActions(const CodeActionInput& input);

class LspSession {
 public:
  explicit LspSession(SessionOptions options) : options_(std::move(options)) {}

  // One parsed message; returns the responses and notifications to send, in order.
  std::vector<nlohmann::json> Handle(const nlohmann::json& message);

  // Checks and publishes every document changed since the last flush (without
  // checks_by_caller, Handle() has done so already).
  std::vector<nlohmann::json> Flush();

  // checks_by_caller: the next document to check (changed ones first, oldest change
  // first; then saved ones to render), and publishing a finished check.
  bool HasCheckWaiting() const { return !dirty_.empty(); }
  bool HasRenderWaiting() const { return !saved_.empty(); }
  std::optional<CheckJob> TakeCheck();
  std::optional<CheckJob> TakeRender();
  std::vector<nlohmann::json> Completed(const CheckJob& job, DocumentCheck checked);

  // A code action request's input (nothing when the document is not open), or the
  // error response to send instead (not initialized, shutting down, bad params).
  struct CodeActionRequest {
    std::optional<CodeActionInput> input;
    nlohmann::json response;  // set when there is nothing to compute
  };
  CodeActionRequest TakeCodeActionRequest(const nlohmann::json& message);

  // The response to a message that was not JSON (JSON-RPC's parse error, id null).
  static nlohmann::json ParseErrorResponse(std::string_view what);

  bool Exited() const { return exited_; }
  // After `exit`: 0 when `shutdown` came first, else 1 (as the protocol says).
  int ExitCode() const { return shutdown_ ? 0 : 1; }

 private:
  struct Document {
    std::filesystem::path path;
    std::string text;
    int64_t version = 0;
    uint64_t revision = 0;  // the session's count of changes when this one came
    std::vector<DocumentFinding> published;
    std::string decision;               // last told to the client (window/logMessage)
    std::vector<std::string> channels;  // iChannel0..3's sampler types as last checked
    // Navigation's analysis of the document and its project, and the session's
    // revision it was made at (any change of an open document makes it stale).
    mutable std::shared_ptr<const ProjectCode> navigation;
    mutable uint64_t navigation_revision = 0;
    // The last render-on-save result: shown instead of a plain check of the same revision.
    std::optional<uint64_t> rendered_revision;
  };

  nlohmann::json Dispatch(const std::string& method, const nlohmann::json& params,
                          std::vector<nlohmann::json>& out);
  void Publish(const std::string& uri, Document& document, DocumentCheck checked,
               std::vector<nlohmann::json>& out);
  void Changed(const std::string& uri, Document& document, std::vector<nlohmann::json>& out);
  // Completion, symbols, definition, hover, references over the document's project.
  nlohmann::json Navigate(const std::string& method, const nlohmann::json& params) const;
  void Configure(const nlohmann::json& settings, std::vector<nlohmann::json>& out);
  CheckJob JobFor(const std::string& uri, const Document& document, bool render) const;
  std::optional<CodeActionInput> CodeActionInputFor(const nlohmann::json& params) const;
  // The error response a request gets before it is dispatched (null when none).
  nlohmann::json Refusal(const std::string& method, const nlohmann::json& id) const;

  SessionOptions options_;
  std::map<std::string, Document> documents_;  // by URI
  std::vector<std::string> dirty_;             // changed, not yet checked
  std::vector<std::string> saved_;             // saved, not yet rendered (render-on-save)
  uint64_t revisions_ = 0;
  // From workspace/didChangeConfiguration (`shaderport.*`): the WebGL context every
  // document is checked for (unset: decided per file, as check does), the severity
  // that fails (unset: the file's .shaderport.toml, else error) and render-on-save.
  std::optional<model::Target> target_;
  std::optional<Severity> fail_on_;
  bool render_on_save_ = false;
  bool initialized_ = false;
  bool shutdown_ = false;
  bool exited_ = false;
};

// The file a URI names: file:///a%20b/x.glsl -> /a b/x.glsl; any other scheme keeps
// its path part (untitled:Untitled-1 -> Untitled-1), so the extension still counts.
std::filesystem::path PathOfUri(std::string_view uri);

}  // namespace shaderport::driver::lsp
