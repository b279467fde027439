// The shaderport command line: a thin layer over the library.
#include <cstdio>
#include <exception>

#include "commands.h"

int main(int argc, char** argv) {
  using namespace shaderport::cli;
  CLI::App app{"shaderport: lint, validate and port ShaderToy and WebGL shaders to WebGL2"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("shaderport ") + SHADERPORT_VERSION);
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
  AddReportCommand(app, exit_code);
  AddMergeCommand(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitUsage;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shaderport: internal error: %s\n", e.what());
    return kExitInternal;
  }
  return exit_code;
}
