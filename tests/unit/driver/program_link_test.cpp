// Program link checks on pairs that Chromium 156 (SwiftShader) compiles stage by stage
// and then refuses to link, from the held-out conformance pages
// (tests/reports/webgl-conformance-heldout.md): uniforms past MAX_*_UNIFORM_VECTORS
// (4096 there), uniform structs whose members differ, stages of two GLSL ES versions.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "driver/check_pipeline.h"
#include "scratch_dir.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;

// The error rule ids of linking `vertex` with `fragment` in a WebGL 1 context.
std::set<std::string> LinkErrors(const std::string& name, const std::string& vertex,
                                 const std::string& fragment) {
  const fs::path dir = testing::ScratchDir("link-" + name);
  std::ofstream(dir / "p.vert") << vertex;
  std::ofstream(dir / "p.frag") << fragment;
  CheckOptions options;
  options.paths = {dir};
  options.use_config = false;
  options.target = model::Target::kWebGL2;
  std::set<std::string> errors;
  for (const FileReport& report : RunCheck(options).report.files) {
    for (const Diagnostic& diagnostic : report.diagnostics) {
      if (diagnostic.severity == Severity::kError) errors.insert(diagnostic.rule_id);
    }
  }
  return errors;
}

// `uniform TYPE u[SIZE];` read at its last element; `component` picks a float of it.
std::string VertexWithUniformArray(const std::string& type, int size,
                                   const std::string& component) {
  return "attribute vec4 a;\nuniform " + type + " u[" + std::to_string(size) +
         "];\nvoid main() { gl_Position = a + vec4(u[" + std::to_string(size - 1) + "]" +
         component + "); }\n";
}

constexpr const char* kFragment =
    "precision mediump float;\nvoid main() { gl_FragColor = vec4(1.0); }\n";

TEST(ProgramLink, UniformVectorsAsChromiumCountsThem) {
  // One vector per matrix column: mat4[1024] is 4096 vectors, mat4[1025] 4100.
  EXPECT_EQ(LinkErrors("mat4-1024", VertexWithUniformArray("mat4", 1024, "[0][0]"), kFragment),
            std::set<std::string>{});
  EXPECT_EQ(LinkErrors("mat4-1025", VertexWithUniformArray("mat4", 1025, "[0][0]"), kFragment),
            std::set<std::string>{"link/uniform-vectors"});
  EXPECT_EQ(LinkErrors("mat3-1366", VertexWithUniformArray("mat3", 1366, "[0][0]"), kFragment),
            std::set<std::string>{"link/uniform-vectors"});
  EXPECT_EQ(LinkErrors("vec2-4097", VertexWithUniformArray("vec2", 4097, ".x"), kFragment),
            std::set<std::string>{"link/uniform-vectors"});
}

TEST(ProgramLink, UniformStructMembersMustAgree) {
  const std::string vertex =
      "struct S { vec4 pos; vec4 color; };\nuniform S uni;\n"
      "void main() { gl_Position = uni.pos; }\n";
  const std::string swapped =
      "precision mediump float;\nstruct S { vec4 color; vec4 pos; };\nuniform S uni;\n"
      "void main() { gl_FragColor = uni.color; }\n";
  EXPECT_EQ(LinkErrors("struct-order", vertex, swapped), std::set<std::string>{"link/uniform"});
  // The vertex shader's default float precision is highp, the fragment's mediump here.
  const std::string same_names =
      "precision mediump float;\nstruct S { vec4 pos; vec4 color; };\nuniform S uni;\n"
      "void main() { gl_FragColor = uni.color; }\n";
  EXPECT_EQ(LinkErrors("struct-precision", vertex, same_names),
            std::set<std::string>{"link/uniform"});
  const std::string highp =
      "precision highp float;\nstruct S { vec4 pos; vec4 color; };\nuniform S uni;\n"
      "void main() { gl_FragColor = uni.color; }\n";
  EXPECT_EQ(LinkErrors("struct-same", vertex, highp), std::set<std::string>{});
}

TEST(ProgramLink, StagesOfTwoVersionsDoNotLink) {
  const std::string fragment300 =
      "#version 300 es\nprecision mediump float;\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n";
  EXPECT_EQ(
      LinkErrors("versions", "attribute vec4 a;\nvoid main() { gl_Position = a; }\n", fragment300),
      std::set<std::string>{"link/version"});
}

}  // namespace
}  // namespace shaderport::driver
