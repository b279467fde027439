// `shaderport rules` (the porting rule reference, as in docs/rules.md) and
// `shaderport explain ID`.
#include <cstdio>
#include <memory>
#include <string>

#include "commands.h"
#include "driver/port/rule_reference.h"

namespace shaderport::cli {

void AddRulesCommand(CLI::App& app, int& exit_code) {
  CLI::App* command =
      app.add_subcommand("rules", "Print the porting rule reference (Markdown, as docs/rules.md)");
  command->callback([&exit_code] {
    std::fputs(driver::RulesMarkdown().c_str(), stdout);
    exit_code = kExitOk;
  });
}

void AddExplainCommand(CLI::App& app, int& exit_code) {
  auto id = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand("explain", "Explain one rule or diagnostic id");
  command->add_option("id", *id, "Rule id, e.g. webgl2/version")->required();
  command->callback([id, &exit_code] {
    const auto text = driver::ExplainRule(*id);
    if (!text) {
      std::fprintf(stderr, "shaderport explain: unknown rule '%s'\n", id->c_str());
      exit_code = kExitUsage;
      return;
    }
    std::fputs(text->c_str(), stdout);
    exit_code = kExitOk;
  });
}

}  // namespace shaderport::cli
