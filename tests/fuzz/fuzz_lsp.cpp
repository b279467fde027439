// libFuzzer target for the language server's message layer (driver/lsp): the input
// is messages, one JSON text a line, after an `initialize`. Properties:
//  - no crash, no exception out of the session;
//  - every message sent is JSON-RPC 2.0, and every request gets exactly one response
//    with its id (errors included); notifications get none;
//  - a line that is not JSON is answered with a parse error by the caller's rule.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "driver/lsp/lsp_session.h"
#include "fuzz_check.h"

namespace {

using Json = nlohmann::json;

void Require(bool ok, const char* what) { shaderport::fuzz::Check(ok, "fuzz_lsp", what); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  shaderport::driver::lsp::LspSession session({"fuzz", {}});
  session.Handle(
      {{"jsonrpc", "2.0"}, {"id", 0}, {"method", "initialize"}, {"params", Json::object()}});
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  size_t start = 0;
  while (start < input.size() && !session.Exited()) {
    size_t end = input.find('\n', start);
    if (end == std::string_view::npos) end = input.size();
    const Json message = Json::parse(input.substr(start, end - start), nullptr, false);
    start = end + 1;
    if (message.is_discarded()) continue;
    const bool request = message.is_object() && message.contains("method") &&
                         message["method"].is_string() && message.contains("id");
    size_t responses = 0;
    for (const Json& out : session.Handle(message)) {
      Require(out.is_object() && out.value("jsonrpc", "") == "2.0", "JSON-RPC 2.0 out");
      if (!out.contains("method")) {
        ++responses;
        if (request) Require(out["id"] == message["id"], "a response carries the request's id");
      }
      (void)out.dump(-1, ' ', false, Json::error_handler_t::replace);
    }
    if (request && !session.Exited()) Require(responses == 1, "one response per request");
  }
  return 0;
}
