#include "driver/lsp/lsp_session.h"

#include <algorithm>
#include <exception>

#include "driver/lsp/lsp_check.h"
#include "driver/lsp/lsp_symbols.h"
#include "driver/lsp/lsp_text.h"

namespace shaderport::driver::lsp {
namespace {

using Json = nlohmann::json;

// JSON-RPC and LSP error codes.
constexpr int kParseError = -32700;
constexpr int kInvalidRequest = -32600;
constexpr int kMethodNotFound = -32601;
constexpr int kInvalidParams = -32602;
constexpr int kServerNotInitialized = -32002;

Json ErrorResponse(const Json& id, int code, std::string_view message) {
  return {{"jsonrpc", "2.0"}, {"id", id}, {"error", {{"code", code}, {"message", message}}}};
}

int Hex(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

bool Overlaps(const Json& a, const Json& b) {
  const auto start = [](const Json& r) {
    return std::pair(r["start"]["line"].get<uint32_t>(), r["start"]["character"].get<uint32_t>());
  };
  const auto end = [](const Json& r) {
    return std::pair(r["end"]["line"].get<uint32_t>(), r["end"]["character"].get<uint32_t>());
  };
  return start(a) <= end(b) && start(b) <= end(a);
}

// Thrown for params a known method cannot use; answered with InvalidParams.
struct BadParams {
  std::string what;
};

const Json& Member(const Json& object, const char* name) {
  if (!object.is_object() || !object.contains(name)) throw BadParams{std::string("no ") + name};
  return object[name];
}

std::string StringMember(const Json& object, const char* name) {
  const Json& value = Member(object, name);
  if (!value.is_string()) throw BadParams{std::string(name) + " is not a string"};
  return value.get<std::string>();
}

// `shaderport/status`: what the document's verdict is against and what it is, for a
// status bar (the VS Code extension shows it).
Json StatusParams(const std::string& uri, int64_t version, const DocumentCheck& checked) {
  std::string summary = checked.target.empty() ? "not checked" : checked.target;
  if (!checked.harness.empty()) summary += ", " + checked.harness;
  for (size_t i = 0; i < checked.channels.size(); ++i) {
    if (checked.channels[i] != "2d") {
      summary += ", iChannel" + std::to_string(i) + " " + checked.channels[i];
    }
  }
  return {{"uri", uri},
          {"version", version},
          {"dialect", checked.dialect},
          {"stage", checked.stage},
          {"harness", checked.harness},
          {"target", checked.target},
          {"channels", checked.channels},
          {"failOn", SeverityName(checked.fail_on)},
          {"fails", checked.fails},
          {"rendered", checked.rendered},
          {"summary", summary}};
}

}  // namespace

std::filesystem::path PathOfUri(std::string_view uri) {
  std::string_view rest = uri;
  if (rest.starts_with("file://")) {
    rest.remove_prefix(7);
  } else if (const size_t colon = rest.find(':'); colon != std::string_view::npos) {
    rest.remove_prefix(colon + 1);
  }
  std::string path;
  for (size_t i = 0; i < rest.size(); ++i) {
    if (rest[i] == '%' && i + 2 < rest.size() && Hex(rest[i + 1]) >= 0 && Hex(rest[i + 2]) >= 0) {
      path += static_cast<char>(Hex(rest[i + 1]) * 16 + Hex(rest[i + 2]));
      i += 2;
    } else {
      path += rest[i];
    }
  }
  return path;
}

Json LspSession::ParseErrorResponse(std::string_view what) {
  return ErrorResponse(nullptr, kParseError, what);
}

std::vector<Json> LspSession::Handle(const Json& message) {
  std::vector<Json> out;
  if (!message.is_object() || !message.contains("method") || !message["method"].is_string()) {
    // A response from the client (we send no requests) or not a message at all.
    if (message.is_object() && message.contains("id") && !message.contains("result") &&
        !message.contains("error")) {
      out.push_back(ErrorResponse(message["id"], kInvalidRequest, "not a JSON-RPC request"));
    } else if (!message.is_object()) {
      out.push_back(ErrorResponse(nullptr, kInvalidRequest, "a message must be a JSON object"));
    }
    return out;
  }
  const std::string method = message["method"];
  const bool request = message.contains("id");
  const Json id = request ? message["id"] : Json();
  const Json params = message.value("params", Json::object());
  if (request) {
    if (Json refusal = Refusal(method, id); !refusal.is_null()) {
      out.push_back(std::move(refusal));
      return out;
    }
  }
  // A request sees every change before it: pending checks are published first
  // (a caller that checks on its own thread orders them itself).
  if (request && !options_.checks_by_caller) out = Flush();
  try {
    Json result = Dispatch(method, params, out);
    if (request) {
      if (result.is_discarded()) {
        out.push_back(ErrorResponse(id, kMethodNotFound, "unknown method " + method));
      } else {
        out.push_back({{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}});
      }
    }
  } catch (const BadParams& bad) {
    if (request) out.push_back(ErrorResponse(id, kInvalidParams, method + ": " + bad.what));
  } catch (const Json::exception& error) {
    if (request) out.push_back(ErrorResponse(id, kInvalidParams, method + ": " + error.what()));
  }
  return out;
}

Json LspSession::Refusal(const std::string& method, const Json& id) const {
  if (!initialized_ && method != "initialize") {
    return ErrorResponse(id, kServerNotInitialized, "initialize comes first");
  }
  if (shutdown_) return ErrorResponse(id, kInvalidRequest, "the server is shutting down");
  return nullptr;
}

Json LspSession::Dispatch(const std::string& method, const Json& params, std::vector<Json>& out) {
  if (method == "initialize") {
    initialized_ = true;
    return {{"capabilities",
             {{"positionEncoding", "utf-16"},
              {"textDocumentSync", {{"openClose", true}, {"change", 2}, {"save", true}}},
              {"documentSymbolProvider", true},
              {"definitionProvider", true},
              {"hoverProvider", true},
              {"referencesProvider", true},
              {"completionProvider", {{"resolveProvider", false}}},
              {"codeActionProvider",
               {{"codeActionKinds",
                 {"quickfix", "source.fixAll.shaderport", "source.convert.webgl2.shaderport"}}}}}},
            {"serverInfo", {{"name", "shaderport"}, {"version", options_.tool_version}}}};
  }
  if (method == "shutdown") {
    shutdown_ = true;
    return nullptr;
  }
  if (method == "exit") {
    exited_ = true;
    return Json::value_t::discarded;
  }
  if (method == "textDocument/didOpen") {
    const Json& item = Member(params, "textDocument");
    const std::string uri = StringMember(item, "uri");
    Document& document = documents_[uri];
    document.path = PathOfUri(uri);
    document.text = StringMember(item, "text");
    document.version = item.value("version", int64_t{0});
    Changed(uri, document, out);
    return Json::value_t::discarded;
  }
  if (method == "textDocument/didChange") {
    const Json& item = Member(params, "textDocument");
    const auto found = documents_.find(StringMember(item, "uri"));
    if (found == documents_.end()) return Json::value_t::discarded;  // not open: ignored
    for (const Json& change : Member(params, "contentChanges")) {
      if (!ApplyChange(found->second.text, change)) throw BadParams{"a malformed change"};
    }
    found->second.version = item.value("version", found->second.version);
    Changed(found->first, found->second, out);
    return Json::value_t::discarded;
  }
  if (method == "textDocument/didClose") {
    const std::string uri = StringMember(Member(params, "textDocument"), "uri");
    std::erase(dirty_, uri);
    std::erase(saved_, uri);
    if (documents_.erase(uri) > 0) {
      ++revisions_;  // its project's other documents now read it from disk
      out.push_back({{"jsonrpc", "2.0"},
                     {"method", "textDocument/publishDiagnostics"},
                     {"params", {{"uri", uri}, {"diagnostics", Json::array()}}}});
    }
    return Json::value_t::discarded;
  }
  if (method == "textDocument/didSave") {
    const std::string uri = StringMember(Member(params, "textDocument"), "uri");
    const auto found = documents_.find(uri);
    if (!render_on_save_ || found == documents_.end()) return Json::value_t::discarded;
    if (!options_.checks_by_caller) {
      Publish(uri, found->second,
              JobFor(uri, found->second, true).Run(options_.rules_with_sections), out);
    } else if (std::find(saved_.begin(), saved_.end(), uri) == saved_.end()) {
      saved_.push_back(uri);
    }
    return Json::value_t::discarded;
  }
  if (method == "workspace/didChangeConfiguration") {
    Configure(Member(params, "settings"), out);
    return Json::value_t::discarded;
  }
  if (method == "textDocument/codeAction") {
    const std::optional<CodeActionInput> input = CodeActionInputFor(params);
    return input ? ComputeCodeActions(*input) : Json::array();
  }
  if (method == "textDocument/completion" || method == "textDocument/documentSymbol" ||
      method == "textDocument/definition" || method == "textDocument/hover" ||
      method == "textDocument/references") {
    return Navigate(method, params);
  }
  // Notifications the session has nothing to do for ($/cancelRequest: the requests
  // it answers are answered before the next message is read; LspServer cancels the
  // ones it queues).
  return Json::value_t::discarded;
}

void LspSession::Configure(const Json& settings, std::vector<Json>& out) {
  // {"shaderport": {"target": "webgl1", "failOn": "warning", "renderOnSave": true}};
  // a missing, null or "" value means the default.
  const Json section =
      settings.is_object() && settings.contains("shaderport") && settings["shaderport"].is_object()
          ? settings["shaderport"]
          : Json::object();
  const auto text = [&](const char* name) {
    const Json& value = section.value(name, Json());
    return value.is_string() ? value.get<std::string>() : std::string();
  };
  const auto complain = [&](const std::string& message) {
    out.push_back({{"jsonrpc", "2.0"},
                   {"method", "window/showMessage"},
                   {"params", {{"type", 1}, {"message", message}}}});
  };
  std::optional<model::Target> target;
  if (const std::string name = text("target"); !name.empty()) {
    target = model::ParseTarget(name);
    if (!target) return complain("shaderport.target must be webgl1 or webgl2, not '" + name + "'");
  }
  std::optional<Severity> fail_on;
  if (const std::string name = text("failOn"); !name.empty()) {
    fail_on = SeverityFromName(name);
    if (!fail_on) {
      return complain("shaderport.failOn must be error, warning or note, not '" + name + "'");
    }
  }
  render_on_save_ =
      section.value("renderOnSave", Json()).is_boolean() && section["renderOnSave"].get<bool>();
  if (target == target_ && fail_on == fail_on_) return;
  target_ = target;
  fail_on_ = fail_on;
  for (auto& [uri, document] : documents_) Changed(uri, document, out);
}

Json LspSession::Navigate(const std::string& method, const Json& params) const {
  const std::string uri = StringMember(Member(params, "textDocument"), "uri");
  const auto found = documents_.find(uri);
  const bool completion = method == "textDocument/completion";
  if (found == documents_.end()) return completion ? Json::array() : Json();  // not open
  const Document& document = found->second;
  // Files of the document's project that are open are read as the editor has them.
  const auto open_text = [this](const std::filesystem::path& path) -> std::optional<std::string> {
    for (const auto& [other_uri, other] : documents_) {
      if (other.path == path) return other.text;
    }
    return std::nullopt;
  };
  // Analysed once per state of the open documents: a cursor moving over unchanged
  // text asks again and again (files that are not open are read when this is built).
  if (document.navigation == nullptr || document.navigation_revision != revisions_) {
    document.navigation = std::make_shared<const ProjectCode>(
        ProjectCode::Of(document.path, uri, document.text, open_text));
    document.navigation_revision = revisions_;
  }
  const ProjectCode& code = *document.navigation;
  if (method == "textDocument/documentSymbol") return DocumentSymbols(code);
  const std::optional<Position> position = PositionFromJson(Member(params, "position"));
  if (!position) throw BadParams{"position is not a position"};
  const uint32_t offset = OffsetOf(document.text, *position);
  if (completion) {
    return Json{{"isIncomplete", false}, {"items", CompletionItems(code, offset)}};
  }
  if (method == "textDocument/references") {
    const bool with_declaration =
        params.contains("context") && params["context"].value("includeDeclaration", false);
    return ReferenceLocations(code, offset, with_declaration);
  }
  if (method == "textDocument/hover") {
    const std::optional<std::string> hover = HoverText(code, offset, document.channels);
    if (!hover) return nullptr;
    return Json{{"contents", {{"kind", "markdown"}, {"value", *hover}}}};
  }
  return DefinitionLocation(code, offset).value_or(Json());
}

CheckJob LspSession::JobFor(const std::string& uri, const Document& document, bool render) const {
  return {uri, document.path, document.text, document.revision, {target_, fail_on_, render}};
}

DocumentCheck CheckJob::Run(const std::vector<std::string>& rules_with_sections) const {
  return CheckDocument(path, uri, text, rules_with_sections, settings);
}

void LspSession::Changed(const std::string& uri, Document& document, std::vector<Json>& out) {
  document.revision = ++revisions_;
  if (!options_.checks_by_caller) {
    return Publish(uri, document, JobFor(uri, document, false).Run(options_.rules_with_sections),
                   out);
  }
  if (std::find(dirty_.begin(), dirty_.end(), uri) == dirty_.end()) dirty_.push_back(uri);
}

std::vector<Json> LspSession::Flush() {
  std::vector<Json> out;
  while (std::optional<CheckJob> job = TakeCheck()) {
    const auto found = documents_.find(job->uri);
    Publish(job->uri, found->second, job->Run(options_.rules_with_sections), out);
  }
  return out;
}

std::optional<CheckJob> LspSession::TakeCheck() {
  while (!dirty_.empty()) {
    const std::string uri = dirty_.front();
    dirty_.erase(dirty_.begin());
    const auto found = documents_.find(uri);
    if (found != documents_.end()) return JobFor(uri, found->second, false);
  }
  return std::nullopt;
}

std::optional<CheckJob> LspSession::TakeRender() {
  while (!saved_.empty()) {
    const std::string uri = saved_.front();
    saved_.erase(saved_.begin());
    const auto found = documents_.find(uri);
    if (found != documents_.end()) return JobFor(uri, found->second, true);
  }
  return std::nullopt;
}

std::vector<Json> LspSession::Completed(const CheckJob& job, DocumentCheck checked) {
  std::vector<Json> out;
  const auto found = documents_.find(job.uri);
  // Closed, changed, or reconfigured since the job began: a newer check is coming.
  if (found == documents_.end() || found->second.revision != job.revision) return out;
  Document& document = found->second;
  if (job.settings.render) {
    document.rendered_revision = job.revision;
  } else if (document.rendered_revision == job.revision) {
    return out;  // the render's findings (a superset) stand for this revision
  }
  Publish(job.uri, document, std::move(checked), out);
  return out;
}

void LspSession::Publish(const std::string& uri, Document& document, DocumentCheck checked,
                         std::vector<Json>& out) {
  // What the verdict is against, told when it is new or changes (a #version line
  // added, a mainImage removed).
  if (!checked.decision.empty() && checked.decision != document.decision) {
    document.decision = checked.decision;
    out.push_back({{"jsonrpc", "2.0"},
                   {"method", "window/logMessage"},
                   {"params",
                    {{"type", 3},
                     {"message", document.path.filename().string() + " is checked as a " +
                                     checked.decision}}}});
  }
  Json diagnostics = Json::array();
  for (const DocumentFinding& finding : checked.findings) diagnostics.push_back(finding.diagnostic);
  out.push_back({{"jsonrpc", "2.0"},
                 {"method", "shaderport/status"},
                 {"params", StatusParams(uri, document.version, checked)}});
  out.push_back(
      {{"jsonrpc", "2.0"},
       {"method", "textDocument/publishDiagnostics"},
       {"params", {{"uri", uri}, {"version", document.version}, {"diagnostics", diagnostics}}}});
  document.published = std::move(checked.findings);
  document.channels = std::move(checked.channels);
}

std::optional<CodeActionInput> LspSession::CodeActionInputFor(const Json& params) const {
  const std::string uri = StringMember(Member(params, "textDocument"), "uri");
  const Json& range = Member(params, "range");
  if (!range.is_object() || !range.contains("start") || !range.contains("end") ||
      !PositionFromJson(range["start"]) || !PositionFromJson(range["end"])) {
    throw BadParams{"range is not a range"};
  }
  const auto found = documents_.find(uri);
  if (found == documents_.end()) return std::nullopt;
  const Document& document = found->second;
  return CodeActionInput{uri, document.path, document.text, range, document.published};
}

LspSession::CodeActionRequest LspSession::TakeCodeActionRequest(const Json& message) {
  const Json id = message.value("id", Json());
  CodeActionRequest request;
  if (Json refusal = Refusal("textDocument/codeAction", id); !refusal.is_null()) {
    request.response = std::move(refusal);
    return request;
  }
  try {
    request.input = CodeActionInputFor(message.value("params", Json::object()));
    if (!request.input) {
      request.response = {{"jsonrpc", "2.0"}, {"id", id}, {"result", Json::array()}};
    }
  } catch (const BadParams& bad) {
    request.response = ErrorResponse(id, kInvalidParams, "textDocument/codeAction: " + bad.what);
  } catch (const Json::exception& error) {
    request.response =
        ErrorResponse(id, kInvalidParams, std::string("textDocument/codeAction: ") + error.what());
  }
  return request;
}

Json ComputeCodeActions(const CodeActionInput& input) {
  Json actions = Json::array();
  bool any_safe = false;
  for (const DocumentFinding& published : input.published) {
    if (published.edits.empty()) continue;
    any_safe = any_safe || published.safe;
    if (!Overlaps(published.diagnostic["range"], input.range)) continue;
    const std::string rule = published.diagnostic["code"];
    actions.push_back({{"title", "Apply the fix of " + rule},
                       {"kind", "quickfix"},
                       {"diagnostics", Json::array({published.diagnostic})},
                       {"isPreferred", published.safe},
                       {"edit", {{"changes", {{input.uri, published.edits}}}}}});
  }
  const Json whole = {
      {"start", ToJson({0, 0})},
      {"end", ToJson(PositionOf(input.text, static_cast<uint32_t>(input.text.size())))}};
  const auto replace_all = [&](const std::string& text) {
    return Json{{"changes", {{input.uri, Json::array({{{"range", whole}, {"newText", text}}})}}}};
  };
  if (any_safe) {
    const std::string fixed = FixDocument(input.path, input.text);
    if (!fixed.empty()) {
      actions.push_back({{"title", "Fix all safe fixes in this file (shaderport fix)"},
                         {"kind", "source.fixAll.shaderport"},
                         {"edit", replace_all(fixed)}});
    }
  }
  // Asked for explicitly (a source action), or offered beside the quick fixes.
  const std::string ported = PortDocument(input.path, input.text);
  if (!ported.empty()) {
    actions.push_back({{"title", "Port this file to WebGL2 (shaderport port)"},
                       {"kind", "source.convert.webgl2.shaderport"},
                       {"edit", replace_all(ported)}});
  }
  return actions;
}

}  // namespace shaderport::driver::lsp
