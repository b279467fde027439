#include <cstdio>

#include "allocator_name.h"
#include "cli_errors.h"
#include "commands.h"
#include "toolchain/toolchain_probe.h"

namespace shaderport::cli {

void AddVersionCommand(CLI::App& app, int& exit_code) {
  auto* command =
      app.add_subcommand("version", "Print versions and prove each shader library runs");
  command->callback([&exit_code] {
    const toolchain::ToolchainReport report = toolchain::ProbeToolchain();
    std::printf("shaderport %s\n", SHADERPORT_VERSION);
    std::printf("glslang %s\n", report.glslang_version.c_str());
    std::printf("SPIR-V: %zu words, SPIRV-Tools validation %s\n", report.spirv_words,
                report.spirv_valid ? "passed" : "FAILED");
    std::printf("SPIRV-Cross: %s\n", report.cross_compiled.starts_with("#version 300 es")
                                         ? "ESSL 300 output"
                                         : "FAILED");
    std::printf("OSMesa: %s (%s)\n", report.osmesa_renderer.c_str(), report.osmesa_version.c_str());
    std::printf("allocator: %s\n", AllocatorName().c_str());
    if (!report.error.empty()) {
      PrintError(report.error);
      exit_code = kExitInternal;
    }
  });
}

}  // namespace shaderport::cli
