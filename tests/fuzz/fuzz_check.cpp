// libFuzzer target for `shaderport check` through the library (driver::RunCheck on an
// in-memory file, as `check --stdin` reads one): the text glslang compiles is prepared
// as browsers read the shader (rules/webgl/glslang_divergence.cpp, directive_text.cpp),
// on any input. No crash, every diagnostic inside a file, the same findings twice.
// The first byte picks the file's kind: a ShaderToy pass, a WebGL 1 or a WebGL 2
// fragment shader, or a vertex shader. Mutated by token_mutator.cpp.
#include <cstdint>
#include <string>

#include "driver/check_pipeline.h"
#include "fuzz_driver_util.h"

namespace {

void Require(bool ok, const char* what) { shaderport::fuzz::Check(ok, "fuzz_check", what); }

std::string Findings(const shaderport::driver::CheckRun& run) {
  std::string all;
  for (const shaderport::FileReport& report : run.report.files) {
    for (const shaderport::Diagnostic& d : report.diagnostics) {
      all += d.rule_id + ":" + std::to_string(d.range.begin) + ":" + d.message + "\n";
    }
  }
  return all;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace shaderport;
  if (size < 1 || size > 16384) return 0;
  static const char* const kNames[] = {"pass.glsl", "webgl1.frag", "webgl2.frag", "shader.vert"};
  const char* name = kNames[data[0] % 4];
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  driver::CheckOptions options;
  options.use_config = false;
  options.jobs = 1;
  options.in_memory = driver::CheckOptions::InMemoryFile{name, driver::ClassifyInputText(text)};
  const driver::CheckRun first = driver::RunCheck(options);
  for (const FileReport& report : first.report.files) {
    for (const Diagnostic& d : report.diagnostics) {
      if (d.range.file == kNoFile) continue;
      Require(report.file != nullptr && d.range.file == report.file->Id()
                  ? d.range.begin <= d.range.end && d.range.end <= report.file->Text().size()
                  : true,
              "diagnostic range inside the file");
    }
  }
  Require(Findings(first) == Findings(driver::RunCheck(options)), "the same findings twice");
  return 0;
}
