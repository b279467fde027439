// `shaderport completion SHELL` and `shaderport man`: both written from the options
// the commands parse (command_table.h).
#include <cstdio>
#include <memory>
#include <string>

#include "cli_errors.h"
#include "command_table.h"
#include "commands.h"
#include "man_page.h"
#include "shell_completion.h"

namespace shaderport::cli {

void AddCompletionCommand(CLI::App& app, int& exit_code) {
  auto shell = std::make_shared<std::string>();
  CLI::App* command =
      app.add_subcommand("completion", "Print the shell completion script for bash, zsh or fish");
  command->add_option("shell", *shell, "bash, zsh or fish")->required();
  command->footer(
      "bash: source <(shaderport completion bash)   zsh: shaderport completion zsh > "
      "\"${fpath[1]}/_shaderport\"   fish: shaderport completion fish > "
      "~/.config/fish/completions/shaderport.fish");
  command->callback([&app, shell, &exit_code] {
    const auto script = CompletionScript(*shell, CommandTable(app));
    if (!script) {
      exit_code = UsageError(UnknownName("shell", *shell, kShellNames));
      return;
    }
    std::fputs(script->c_str(), stdout);
  });
}

void AddManCommand(CLI::App& app, int& /*exit_code*/) {
  CLI::App* command = app.add_subcommand("man", "Print the manual page (roff), shaderport(1)");
  command->callback(
      [&app] { std::fputs(ManPage(CommandTable(app), SHADERPORT_VERSION).c_str(), stdout); });
}

}  // namespace shaderport::cli
