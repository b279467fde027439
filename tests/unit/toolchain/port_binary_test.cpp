// The WebGL1 corpus files (corpus/ssao) through the real `shaderport port --emit spirv`, once
// the binary has that command: each output must pass the spirv-val command-line tool. Until
// then the same files are covered by emit_test_util.h's mechanical port.
#include <gtest/gtest.h>

#include "emit_test_util.h"

namespace shaderport::toolchain {
namespace {

namespace fs = std::filesystem;
using testing::ReadText;

int RunQuietly(const std::string& command) {
  return std::system((command + " > /dev/null 2>&1").c_str());
}

TEST(PortBinary, WebGl1CorpusEmitsSpirvThatSpirvValAccepts) {
  const fs::path binary = SHADERPORT_BINARY;
  if (!fs::exists(binary)) GTEST_SKIP() << "no shaderport binary at " << binary;
  const fs::path dir = fs::temp_directory_path() / ("shaderport-port-" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path help = dir / "help.txt";
  if (std::system(
          ("'" + binary.string() + "' port --help > '" + help.string() + "' 2>&1").c_str()) != 0 ||
      ReadText(help).find("--emit") == std::string::npos) {
    fs::remove_all(dir);
    GTEST_SKIP() << "shaderport has no `port --emit` yet";
  }
  int checked = 0;
  for (const auto& entry :
       fs::directory_iterator(fs::path(SHADERPORT_SOURCE_DIR) / "corpus/ssao")) {
    SCOPED_TRACE(entry.path().filename().string());
    const fs::path out = dir / entry.path().stem();
    fs::create_directories(out);
    // The exit status also reflects port's own findings; the .spv files are what count here.
    RunQuietly("'" + binary.string() + "' port --emit spirv --out-dir '" + out.string() + "' '" +
               entry.path().string() + "'");
    for (const auto& produced : fs::directory_iterator(out)) {
      if (produced.path().extension() != ".spv") continue;
      EXPECT_EQ(RunQuietly("spirv-val --target-env opengl4.5 '" + produced.path().string() + "'"),
                0)
          << produced.path();
      ++checked;
    }
  }
  fs::remove_all(dir);
  EXPECT_EQ(checked, 9);
}

}  // namespace
}  // namespace shaderport::toolchain
