// The shaderport command line: a thin layer over the library.
#include <exception>

#include "cli_errors.h"
#include "commands.h"
#include "parse_errors.h"

int main(int argc, char** argv) {
  using namespace shaderport::cli;
  CLI::App app{"shaderport: lint, validate and port ShaderToy and WebGL shaders to WebGL2",
               "shaderport"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("shaderport ") + SHADERPORT_VERSION);
  app.footer(
      "Run 'shaderport help COMMAND' (or 'shaderport COMMAND --help') for a command's options.");
  int exit_code = kExitOk;
  AddVersionCommand(app, exit_code);
  AddCheckCommand(app, exit_code);
  AddDumpCommand(app, exit_code);
  AddSummaryCommand(app, exit_code);
  AddRenderCommand(app, exit_code);
  AddFixCommand(app, exit_code);
  AddPortCommand(app, exit_code);
  AddRulesCommand(app, exit_code);
  AddExplainCommand(app, exit_code);
  AddExplainFileCommand(app, exit_code);
  AddReportCommand(app, exit_code);
  AddMergeCommand(app, exit_code);
  AddCompletionCommand(app, exit_code);
  AddManCommand(app, exit_code);
  AddLspCommand(app, exit_code);
  try {
    if (const auto handled = HandleCommandWord(app, argc, argv)) return *handled;
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return UsageError(DescribeParseError(app, e));
  } catch (const std::exception& e) {
    PrintError(std::string("internal error: ") + e.what());
    return kExitInternal;
  }
  return exit_code;
}
