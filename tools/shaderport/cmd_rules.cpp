// `shaderport rules` (the porting rule reference, as in docs/rules.md) and
// `shaderport explain ID`.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli_errors.h"
#include "commands.h"
#include "diag/rule_catalog.h"
#include "driver/port/rule_reference.h"

namespace shaderport::cli {
namespace {

// Every id `explain` knows: the porting rules and the diagnostic catalog.
std::vector<std::string> KnownRuleIds() {
  std::vector<std::string> ids = driver::PortingRuleIds();
  for (const RuleDescription& rule : RuleCatalog()) ids.emplace_back(rule.id);
  return ids;
}

}  // namespace

void AddRulesCommand(CLI::App& app, int& exit_code) {
  auto list = std::make_shared<bool>(false);
  CLI::App* command =
      app.add_subcommand("rules", "Print the porting rule reference (Markdown, as docs/rules.md)");
  command->add_flag("--list", *list, "One line per rule: id, scope and summary");
  command->callback([list, &exit_code] {
    std::fputs((*list ? driver::RulesList() : driver::RulesMarkdown()).c_str(), stdout);
    exit_code = kExitOk;
  });
}

void AddExplainCommand(CLI::App& app, int& exit_code) {
  auto id = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand("explain", "Explain one rule or diagnostic id");
  command->add_option("id", *id, "Rule id, e.g. port/version")->required();
  command->callback([id, &exit_code] {
    const auto text = driver::ExplainRule(*id);
    if (!text) {
      exit_code = UsageError("unknown rule '" + *id + "'" + DidYouMean(*id, KnownRuleIds()) +
                             " (run 'shaderport rules' for the porting rules)");
      return;
    }
    std::fputs(text->c_str(), stdout);
    exit_code = kExitOk;
  });
}

}  // namespace shaderport::cli
