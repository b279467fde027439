// libFuzzer target for the two TOML readers a user's files reach: .shaderport.toml
// (driver/config) and a harness dialect (`--dialect FILE`, model/harness_dialect).
// The same bytes go to both. No crash, no exception, diagnostics inside the file
// and no more of them than the text has lines (plus one), and the queries
// (rule levels, include/exclude globs, per-file settings) stay bounded.
#include <cstdint>
#include <string>

#include "driver/config/config.h"
#include "fuzz_check.h"
#include "model/harness_dialect.h"
#include "rule/harness_dialect_detect.h"
#include "rule/harness_dialect_file.h"

namespace {

void Require(bool ok, const char* what) { shaderport::fuzz::Check(ok, "fuzz_config", what); }

void CheckDiagnostics(const shaderport::SourceFile& file,
                      const shaderport::DiagnosticList& diagnostics) {
  for (const auto& d : diagnostics) {
    Require(d.range.file == file.Id(), "diagnostic in the file");
    Require(d.range.begin <= d.range.end && d.range.end <= file.Text().size(), "diagnostic range");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace shaderport;
  if (size > 65536) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  SourceManager sources;
  const driver::ConfigResult config = driver::ParseConfig(text, "/p/.shaderport.toml", sources);
  const SourceFile& config_file = sources.Get(sources.Size() - 1);
  CheckDiagnostics(config_file, config.diagnostics);
  // Each bad entry is one diagnostic; a key or value needs at least a few bytes.
  Require(config.diagnostics.size() <= size + 1, "config diagnostics bounded");
  for (const char* rule : {"glslang/missing-precision", "suppression/unused", "port/x", ""}) {
    (void)driver::RuleLevelFor(config.config, rule);
  }
  for (const char* path : {"/p/shaders/a.frag", "/p/third_party/x/y/z.gen.glsl", "/q/b.vert",
                           "/p/a/b/c/d/e/f/g/h/i/j/k/l/m/n/o/p/q/r/s/t/u/v/w/x/y/z.glsl"}) {
    (void)driver::IsIncluded(config.config, path);
    (void)driver::SettingsFor(config.config, path);
  }

  const SourceFile& dialect_file = sources.Add("fuzz-dialect.toml", text);
  const rule::DialectLoadResult dialect = rule::ParseDialect(dialect_file);
  CheckDiagnostics(dialect_file, dialect.diagnostics);
  Require(dialect.diagnostics.size() <= size + 1, "dialect diagnostics bounded");
  if (dialect.dialect) {
    for (const model::ProvidedVariable& v : dialect.dialect->provides)
      (void)model::DeclarationOf(v);
    const model::HarnessDialect candidates[] = {*dialect.dialect};
    (void)rule::DetectDialectInText(candidates,
                                    "void mainImage(out vec4 c, in vec2 p) { c = vec4(iTime); }");
  }
  return 0;
}
