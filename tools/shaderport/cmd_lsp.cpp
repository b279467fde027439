// `shaderport lsp`: the language server on standard input and output.
#include <cstdio>

#include "commands.h"
#include "driver/lsp/lsp_server.h"
#include "driver/port/rule_reference.h"
#include "lsp_framing.h"

namespace shaderport::cli {
namespace {

void Send(const nlohmann::json& message) {
  // Invalid UTF-8 in a message (a shader's bytes) is replaced, never thrown on.
  WriteFramedMessage(stdout,
                     message.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
}

int RunLsp() {
  driver::lsp::LspServer server({SHADERPORT_VERSION, driver::PortingRuleIds()}, Send);
  while (std::optional<FramedMessage> framed = ReadFramedMessage(stdin)) {
    if (!framed->error.empty()) {
      server.ReceiveUnreadable(framed->error);
      continue;
    }
    const nlohmann::json message = nlohmann::json::parse(framed->body, nullptr, false);
    if (message.is_discarded()) {
      server.ReceiveUnreadable("not JSON");
      continue;
    }
    server.Receive(message);
    if (server.Exited()) return server.ExitCode();
  }
  return 1;  // the client went away without `exit`
}

}  // namespace

void AddLspCommand(CLI::App& app, int& exit_code) {
  CLI::App* command =
      app.add_subcommand("lsp", "Run the language server (LSP 3.17) on standard input and output");
  // Clients that start servers with `--stdio` (VS Code's TransportKind.stdio) get the
  // one transport there is.
  static bool stdio = true;
  command->add_flag("--stdio", stdio,
                    "Talk over standard input and output (the default and only way)");
  command->callback([&exit_code] { exit_code = RunLsp(); });
}

}  // namespace shaderport::cli
