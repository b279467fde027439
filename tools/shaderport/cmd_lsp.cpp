// `shaderport lsp`: the language server on standard input and output.
#include <poll.h>
#include <unistd.h>

#include <cstdio>

#include "commands.h"
#include "driver/lsp/lsp_session.h"
#include "driver/port/rule_reference.h"
#include "lsp_framing.h"

namespace shaderport::cli {
namespace {

// True when the client has already sent more (a message waits on standard input).
bool MoreInputWaiting() {
  pollfd input{STDIN_FILENO, POLLIN, 0};
  return ::poll(&input, 1, 0) > 0 && (input.revents & POLLIN) != 0;
}

void Send(const nlohmann::json& message) {
  // Invalid UTF-8 in a message (a shader's bytes) is replaced, never thrown on.
  WriteFramedMessage(stdout,
                     message.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
}

int RunLsp() {
  driver::lsp::LspSession session({SHADERPORT_VERSION, driver::PortingRuleIds(), true});
  while (std::optional<FramedMessage> framed = ReadFramedMessage(stdin)) {
    if (!framed->error.empty()) {
      WriteFramedMessage(stdout, driver::lsp::LspSession::ParseErrorResponse(framed->error).dump());
      continue;
    }
    const nlohmann::json message = nlohmann::json::parse(framed->body, nullptr, false);
    if (message.is_discarded()) {
      WriteFramedMessage(stdout, driver::lsp::LspSession::ParseErrorResponse("not JSON").dump());
      continue;
    }
    for (const nlohmann::json& out : session.Handle(message)) Send(out);
    if (session.Exited()) return session.ExitCode();
    // Keystrokes already sent make the pending check stale: check when none waits.
    // (Input already in stdin's buffer is not seen: that only checks once more.)
    if (!MoreInputWaiting()) {
      for (const nlohmann::json& out : session.Flush()) Send(out);
    }
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
