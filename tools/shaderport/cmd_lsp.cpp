// `shaderport lsp`: the language server on standard input and output.
#include <cstdio>

#include "commands.h"
#include "driver/lsp/lsp_session.h"
#include "driver/port/rule_reference.h"
#include "lsp_framing.h"

namespace shaderport::cli {
namespace {

int RunLsp() {
  driver::lsp::LspSession session({SHADERPORT_VERSION, driver::PortingRuleIds()});
  while (std::optional<FramedMessage> framed = ReadFramedMessage(stdin)) {
    if (!framed->error.empty()) {
      WriteFramedMessage(stdout, driver::lsp::LspSession::ParseErrorResponse(framed->error).dump());
      continue;
    }
    const nlohmann::json message = nlohmann::json::parse(framed->body, nullptr, false);
    if (message.is_discarded()) {
      WriteFramedMessage(stdout,
                         driver::lsp::LspSession::ParseErrorResponse("not JSON").dump());
      continue;
    }
    for (const nlohmann::json& out : session.Handle(message)) {
      // Invalid UTF-8 in a message (a shader's bytes) is replaced, never thrown on.
      WriteFramedMessage(stdout, out.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
    }
    if (session.Exited()) return session.ExitCode();
  }
  return 1;  // the client went away without `exit`
}

}  // namespace

void AddLspCommand(CLI::App& app, int& exit_code) {
  CLI::App* command = app.add_subcommand(
      "lsp", "Run the language server (LSP 3.17) on standard input and output");
  command->callback([&exit_code] { exit_code = RunLsp(); });
}

}  // namespace shaderport::cli
