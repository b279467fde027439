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
  if (request && !initialized_ && method != "initialize") {
    out.push_back(ErrorResponse(id, kServerNotInitialized, "initialize comes first"));
    return out;
  }
  if (request && shutdown_) {
    out.push_back(ErrorResponse(id, kInvalidRequest, "the server is shutting down"));
    return out;
  }
  // A request sees every change before it: pending checks are published first.
  if (request) out = Flush();
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

Json LspSession::Dispatch(const std::string& method, const Json& params, std::vector<Json>& out) {
  if (method == "initialize") {
    initialized_ = true;
    return {{"capabilities",
             {{"positionEncoding", "utf-16"},
              {"textDocumentSync", {{"openClose", true}, {"change", 2}}},
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
    if (documents_.erase(uri) > 0) {
      out.push_back({{"jsonrpc", "2.0"},
                     {"method", "textDocument/publishDiagnostics"},
                     {"params", {{"uri", uri}, {"diagnostics", Json::array()}}}});
    }
    return Json::value_t::discarded;
  }
  if (method == "workspace/didChangeConfiguration") {
    // {"settings": {"shaderport": {"target": "webgl1"}}}; null or "" decides per file.
    const Json& settings = Member(params, "settings");
    std::optional<model::Target> target;
    if (settings.is_object() && settings.contains("shaderport") &&
        settings["shaderport"].is_object()) {
      const Json& value = settings["shaderport"].value("target", Json());
      if (value.is_string() && !value.get<std::string>().empty()) {
        target = model::ParseTarget(value.get<std::string>());
        if (!target) {
          out.push_back({{"jsonrpc", "2.0"},
                         {"method", "window/showMessage"},
                         {"params",
                          {{"type", 1},
                           {"message", "shaderport.target must be webgl1 or webgl2, not '" +
                                           value.get<std::string>() + "'"}}}});
          return Json::value_t::discarded;
        }
      }
    }
    if (target != target_) {
      target_ = target;
      for (auto& [uri, document] : documents_) Changed(uri, document, out);
    }
    return Json::value_t::discarded;
  }
  if (method == "textDocument/codeAction") return CodeActions(params);
  if (method == "textDocument/completion") {
    const std::string uri = StringMember(Member(params, "textDocument"), "uri");
    const auto found = documents_.find(uri);
    if (found == documents_.end()) return Json::array();
    return Json{{"isIncomplete", false},
                {"items", CompletionItems(found->second.path, found->second.text)}};
  }
  if (method == "textDocument/documentSymbol" || method == "textDocument/definition" ||
      method == "textDocument/hover" || method == "textDocument/references") {
    const std::string uri = StringMember(Member(params, "textDocument"), "uri");
    const auto found = documents_.find(uri);
    if (found == documents_.end()) return nullptr;  // not open: nothing known
    const Document& document = found->second;
    if (method == "textDocument/documentSymbol") {
      return DocumentSymbols(document.path, document.text);
    }
    const std::optional<Position> position = PositionFromJson(Member(params, "position"));
    if (!position) throw BadParams{"position is not a position"};
    const uint32_t offset = OffsetOf(document.text, *position);
    if (method == "textDocument/references") {
      const bool with_declaration =
          params.contains("context") && params["context"].value("includeDeclaration", false);
      Json locations = Json::array();
      for (const Json& range :
           ReferenceRanges(document.path, document.text, offset, with_declaration)) {
        locations.push_back({{"uri", uri}, {"range", range}});
      }
      return locations;
    }
    if (method == "textDocument/hover") {
      const std::optional<std::string> hover = HoverText(document.path, document.text, offset);
      if (!hover) return nullptr;
      return Json{{"contents", {{"kind", "markdown"}, {"value", *hover}}}};
    }
    const std::optional<Json> range = DefinitionRange(document.path, document.text, offset);
    if (!range) return nullptr;
    return Json{{"uri", uri}, {"range", *range}};
  }
  // Notifications the session has nothing to do for ($/cancelRequest: every request
  // is answered before the next message is read).
  return Json::value_t::discarded;
}

void LspSession::Changed(const std::string& uri, Document& document, std::vector<Json>& out) {
  if (!options_.defer_checks) return Publish(uri, document, out);
  if (std::find(dirty_.begin(), dirty_.end(), uri) == dirty_.end()) dirty_.push_back(uri);
}

std::vector<Json> LspSession::Flush() {
  std::vector<Json> out;
  for (const std::string& uri : dirty_) {
    const auto found = documents_.find(uri);
    if (found != documents_.end()) Publish(uri, found->second, out);
  }
  dirty_.clear();
  return out;
}

void LspSession::Publish(const std::string& uri, Document& document, std::vector<Json>& out) {
  document.published.clear();
  Json diagnostics = Json::array();
  DocumentCheck checked =
      CheckDocument(document.path, uri, document.text, options_.rules_with_sections, target_);
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
  for (DocumentFinding& finding : checked.findings) {
    diagnostics.push_back(finding.diagnostic);
    document.published.push_back(
        {std::move(finding.diagnostic), std::move(finding.edits), finding.safe});
  }
  out.push_back(
      {{"jsonrpc", "2.0"},
       {"method", "textDocument/publishDiagnostics"},
       {"params", {{"uri", uri}, {"version", document.version}, {"diagnostics", diagnostics}}}});
}

Json LspSession::CodeActions(const Json& params) {
  const std::string uri = StringMember(Member(params, "textDocument"), "uri");
  const Json& range = Member(params, "range");
  Json actions = Json::array();
  const auto found = documents_.find(uri);
  if (found == documents_.end()) return actions;
  const Document& document = found->second;
  bool any_safe = false;
  for (const Published& published : document.published) {
    if (published.edits.empty()) continue;
    any_safe = any_safe || published.safe;
    if (!Overlaps(published.diagnostic["range"], range)) continue;
    const std::string rule = published.diagnostic["code"];
    actions.push_back({{"title", "Apply the fix of " + rule},
                       {"kind", "quickfix"},
                       {"diagnostics", Json::array({published.diagnostic})},
                       {"isPreferred", published.safe},
                       {"edit", {{"changes", {{uri, published.edits}}}}}});
  }
  const Json whole = {
      {"start", ToJson({0, 0})},
      {"end", ToJson(PositionOf(document.text, static_cast<uint32_t>(document.text.size())))}};
  if (any_safe) {
    const std::string fixed = FixDocument(document.path, document.text);
    if (!fixed.empty()) {
      actions.push_back(
          {{"title", "Fix all safe fixes in this file (shaderport fix)"},
           {"kind", "source.fixAll.shaderport"},
           {"edit",
            {{"changes", {{uri, Json::array({{{"range", whole}, {"newText", fixed}}})}}}}}});
    }
  }
  // Asked for explicitly (a source action), or offered beside the quick fixes.
  const std::string ported = PortDocument(document.path, document.text);
  if (!ported.empty()) {
    actions.push_back(
        {{"title", "Port this file to WebGL2 (shaderport port)"},
         {"kind", "source.convert.webgl2.shaderport"},
         {"edit", {{"changes", {{uri, Json::array({{{"range", whole}, {"newText", ported}}})}}}}}});
  }
  return actions;
}

}  // namespace shaderport::driver::lsp
