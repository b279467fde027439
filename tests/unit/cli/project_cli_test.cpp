// ShaderToy projects (JSON exports, corpus records, .jsonl, project folders) through
// the binary: check, fix -i, port, render.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/cli_test_util.h"
#include "cli/temp_project.h"

namespace shaderport::testing {
namespace {

// Buffer A feeds itself back (keeps alpha), Image reads it; Common has a helper.
// Buffer A line 2 holds a type error the site rejects, fixable (`vec3(1.0)`).
std::string Export(const std::string& buffer_code) {
  nlohmann::ordered_json buffer_input = {{"id", "4dXGR8"},
                                         {"filepath", "/media/previz/buffer00.png"},
                                         {"type", "buffer"},
                                         {"channel", 0}};
  nlohmann::ordered_json shader = {
      {"Shader",
       {{"info", {{"id", "tst001"}, {"name", "Feedback </script><b>"}, {"username", "me"}}},
        {"renderpass",
         {{{"inputs", {buffer_input}},
           {"outputs", {{{"id", "4dfGRr"}, {"channel", 0}}}},
           {"code",
            "void mainImage(out vec4 o, in vec2 p) {\n  o = texture(iChannel0, p / "
            "iResolution.xy);\n}\n"},
           {"name", "Image"},
           {"type", "image"}},
          {{"inputs", {buffer_input}},
           {"outputs", {{{"id", "4dXGR8"}, {"channel", 0}}}},
           {"code", buffer_code},
           {"name", "Buffer A"},
           {"type", "buffer"}},
          {{"inputs", nlohmann::ordered_json::array()},
           {"outputs", nlohmann::ordered_json::array()},
           {"code", "float half_of(float x) { return x * 0.5; }\n"},
           {"name", "Common"},
           {"type", "common"}}}}}}};
  return shader.dump(1);
}

constexpr const char* kBufferWithError =
    "void mainImage(out vec4 o, in vec2 p) {\n  vec3 c = 1.0; // \xC3\xA9\n"
    "  o = vec4(c * half_of(p.x / iResolution.x), 0.5);\n}\n";

TEST(ProjectCli, CheckReportsFindingsOnTheTabAndExitsOne) {
  TempProject project("project-check");
  project.Write("toy.json", Export(kBufferWithError));
  const CommandResult result = RunShaderport("check toy.json", project.Root());
  EXPECT_EQ(result.exit_code, 1) << result.out << result.err;
  EXPECT_NE(result.out.find("toy.json#Buffer A:2:"), std::string::npos) << result.out;
  EXPECT_EQ(result.out.find("toy.json#Image:"), std::string::npos) << result.out;
  // The summary counts the tabs as tabs of one project, not as three files.
  EXPECT_NE(result.out.find("in 1 file (3 tabs of 1 ShaderToy project checked)"), std::string::npos)
      << result.out;
}

TEST(ProjectCli, SarifPointsAtTheJsonBytesAndNamesThePass) {
  TempProject project("project-sarif");
  const std::string document = Export(kBufferWithError);
  project.Write("toy.json", document);
  const CommandResult result = RunShaderport("check --format sarif toy.json", project.Root());
  const nlohmann::json sarif = nlohmann::json::parse(result.out);
  const nlohmann::json& results = sarif["runs"][0]["results"];
  ASSERT_FALSE(results.empty());
  const nlohmann::json& location = results[0]["locations"][0];
  EXPECT_EQ(location["physicalLocation"]["artifactLocation"]["uri"], "toy.json");
  EXPECT_EQ(location["logicalLocations"][0]["name"], "Buffer A");
  EXPECT_EQ(location["logicalLocations"][0]["properties"]["shaderport/passLine"], 2);
  // The region is where the flagged code sits inside the JSON string.
  const int line = location["physicalLocation"]["region"]["startLine"];
  const int column = location["physicalLocation"]["region"]["startColumn"];
  size_t at = 0;
  for (int l = 1; l < line; ++l) at = document.find('\n', at) + 1;
  EXPECT_EQ(document.substr(at + static_cast<size_t>(column) - 1, 1), "=") << line << ":" << column;
}

TEST(ProjectCli, FixInPlaceRewritesOnlyTheCodeStrings) {
  TempProject project("project-fix");
  const std::string document = Export(kBufferWithError);
  const auto path = project.Write("toy.json", document);
  const CommandResult result = RunShaderport("fix -i toy.json", project.Root());
  EXPECT_LE(result.exit_code, 1) << result.err;
  const std::string fixed = ReadWholeFile(path);
  std::string expected = document;
  const std::string from = "vec3 c = 1.0;";
  expected.replace(expected.find(from), from.size(), "vec3 c = vec3(1.0);");
  EXPECT_EQ(fixed, expected);
  EXPECT_EQ(RunShaderport("check toy.json", project.Root()).exit_code, 0);
}

TEST(ProjectCli, PortWritesOneCompilingShaderPerPassAndBuffersKeepAlpha) {
  TempProject project("project-port");
  project.Write("toy.json", Export(kBufferWithError));
  const CommandResult result = RunShaderport("port toy.json --out-dir out", project.Root());
  EXPECT_EQ(result.exit_code, 0) << result.err;
  const std::string buffer = ReadWholeFile(project.Root() / "out/toy/buffer-a.frag");
  const std::string image = ReadWholeFile(project.Root() / "out/toy/image.frag");
  EXPECT_NE(buffer.find("float half_of"), std::string::npos);  // Common inlined
  EXPECT_NE(buffer.find("vec3 c = vec3(1.0);"), std::string::npos);
  EXPECT_NE(image.find(".xyz, 1.0)"), std::string::npos);  // the Image forces alpha
  EXPECT_EQ(buffer.find(".xyz, 1.0)"), std::string::npos);
  EXPECT_FALSE(project.Exists("out/toy/common.frag"));
  for (const char* file : {"out/toy/buffer-a.frag", "out/toy/image.frag"}) {
    const std::string command =
        "glslangValidator '" + (project.Root() / file).string() + "' >/dev/null";
    EXPECT_EQ(std::system(command.c_str()), 0) << file;
  }
  // Several files need --out-dir.
  EXPECT_EQ(RunShaderport("port toy.json", project.Root()).exit_code, 2);
}

TEST(ProjectCli, FolderLayoutRoundTripsAndRendersAsTheJson) {
  TempProject project("project-folder");
  std::string code = kBufferWithError;
  code.replace(code.find("vec3 c = 1.0;"), 13, "vec3 c = vec3(1.0);");
  project.Write("toy.json", Export(code));
  ASSERT_EQ(RunShaderport("port --emit folder toy.json --out-dir f", project.Root()).exit_code, 0);
  for (const char* file :
       {"f/toy/image.glsl", "f/toy/buffer-a.glsl", "f/toy/common.glsl", "f/toy/shadertoy.toml"})
    EXPECT_TRUE(project.Exists(file)) << file;
  EXPECT_EQ(RunShaderport("check f/toy", project.Root()).exit_code, 0);
  const CommandResult json =
      RunShaderport("render toy.json --frames 3 -o a.png --hermetic", project.Root());
  const CommandResult folder =
      RunShaderport("render f/toy --frames 3 -o b.png --hermetic", project.Root());
  ASSERT_EQ(json.exit_code, 0) << json.err;
  ASSERT_EQ(folder.exit_code, 0) << folder.err;
  EXPECT_EQ(ReadWholeFile(project.Root() / "a.png"), ReadWholeFile(project.Root() / "b.png"));
}

// check --render draws a project as `render` does: Buffer A (one flat colour) feeds
// Image, which shows it. Drawn tab by tab, Buffer A alone would be the flat picture and
// Image would show a procedural texture; drawn whole, the Image is the flat one.
TEST(ProjectCli, CheckRenderDrawsTheWholeProject) {
  TempProject project("project-check-render");
  nlohmann::json toy = nlohmann::json::parse(
      Export("void mainImage(out vec4 o, in vec2 p) {\n  o = vec4(0.8, 0.2, 0.1, 1.0);\n}\n"));
  toy["Shader"]["renderpass"][0]["code"] =
      "void mainImage(out vec4 o, in vec2 p) {\n  o = texture(iChannel0, p / iResolution.xy);\n}\n";
  project.Write("toy.json", toy.dump(1));
  const CommandResult result =
      RunShaderport("check --render --render-size 16 toy.json", project.Root());
  EXPECT_LE(result.exit_code, 1) << result.err;
  EXPECT_NE(result.out.find("toy.json#Image:"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("render/single-colour"), std::string::npos) << result.out;
  EXPECT_EQ(result.out.find("toy.json#Buffer A:"), std::string::npos) << result.out;
}

TEST(ProjectCli, BrokenDocumentsAreUserErrors) {
  TempProject project("project-broken");
  project.Write("bad.json", "{\"Shader\": {\"renderpass\": [}");
  const CommandResult check = RunShaderport("check bad.json", project.Root());
  EXPECT_EQ(check.exit_code, 1);
  EXPECT_NE(check.out.find("bad.json:1:28: error: invalid JSON"), std::string::npos) << check.out;
  EXPECT_NE(check.out.find("[input/invalid-project]"), std::string::npos);
  const CommandResult fix = RunShaderport("fix -i bad.json", project.Root());
  EXPECT_EQ(fix.exit_code, 1);
  EXPECT_EQ(ReadWholeFile(project.Root() / "bad.json"), "{\"Shader\": {\"renderpass\": [}");
  // A walked directory takes ShaderToy documents, not other JSON.
  project.Write("dir/package.json", "{\"name\": \"x\"}");
  project.Write("dir/toy.json", Export("void mainImage(out vec4 o, in vec2 p) { o = vec4(1); }\n"));
  const CommandResult walk = RunShaderport("check dir", project.Root());
  EXPECT_EQ(walk.exit_code, 0) << walk.out;
  EXPECT_NE(walk.out.find("(3 tabs of 1 ShaderToy project checked)"), std::string::npos)
      << walk.out;
  // A document that cannot be read is reported, but is no checked tab; a shader file
  // beside a project is counted as a file.
  project.Write("dir/plain.frag", kWebGL1Fragment);
  const CommandResult mixed = RunShaderport("check dir bad.json", project.Root());
  EXPECT_NE(mixed.out.find("in 1 file (1 file and 3 tabs of 1 ShaderToy project checked)"),
            std::string::npos)
      << mixed.out;
}

}  // namespace
}  // namespace shaderport::testing
