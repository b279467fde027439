#include "driver/project/html_page.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "driver/port/port_file.h"
#include "driver/project/json_project_reader.h"
#include "driver/project/port_document.h"
#include "driver/project/port_project.h"

namespace shaderport::driver::project {
namespace {

size_t Count(const std::string& haystack, const std::string& needle) {
  size_t n = 0;
  for (size_t at = haystack.find(needle); at != std::string::npos;
       at = haystack.find(needle, at + 1)) {
    ++n;
  }
  return n;
}

std::string Lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// The text of the page's JSON script element.
std::string EmbeddedJson(const std::string& page) {
  const std::string open = "<script type=\"application/json\" id=\"sp-project\">";
  const size_t begin = page.find(open) + open.size();
  return page.substr(begin, page.find("</script>", begin) - begin);
}

PageProject Hostile() {
  PageProject project;
  project.name =
      "</script><script>document.body.setAttribute('x','1')</script><!-- & <img src=x "
      "onerror=alert(1)>";
  PagePass pass;
  pass.tab_name = "Image </SCRIPT ><b>";
  pass.fragment_shader = "// </script><script>alert(2)</script> <!-- \xe2\x80\xa8 \xe2\x80\xa9\n";
  pass.port_errors = "bad byte \xff here";
  project.passes.push_back(pass);
  return project;
}

TEST(HtmlPage, NoTextOfTheProjectEndsTheScriptOrOpensMarkup) {
  const std::string page = BuildProjectPage(Hostile());
  // Only the page's own two script elements open and close.
  EXPECT_EQ(Count(Lower(page), "<script"), 2u);
  EXPECT_EQ(Count(Lower(page), "</script"), 2u);
  EXPECT_EQ(page.find("<!--"), std::string::npos);
  EXPECT_EQ(page.find("<img"), std::string::npos);
  EXPECT_EQ(page.find("<b>"), std::string::npos);
  const std::string json = EmbeddedJson(page);
  EXPECT_EQ(json.find_first_of("<>&"), std::string::npos);
  EXPECT_EQ(json.find("\xe2\x80\xa8"), std::string::npos);
  EXPECT_EQ(json.find("\xe2\x80\xa9"), std::string::npos);
}

TEST(HtmlPage, EmbeddedJsonReadsBackAsTheProject) {
  const PageProject project = Hostile();
  const nlohmann::json read = nlohmann::json::parse(EmbeddedJson(BuildProjectPage(project)));
  EXPECT_EQ(read["name"], project.name);
  EXPECT_EQ(read["passes"][0]["name"], project.passes[0].tab_name);
  EXPECT_EQ(read["passes"][0]["code"], project.passes[0].fragment_shader);
  // An invalid byte becomes U+FFFD instead of failing the page.
  EXPECT_EQ(read["passes"][0]["portErrors"], "bad byte \xef\xbf\xbd here");
}

TEST(HtmlPage, TitleIsEscapedText) {
  const std::string page = BuildProjectPage(Hostile());
  EXPECT_NE(page.find("<title>&lt;/script&gt;&lt;script&gt;document.body.setAttribute(&#39;x&#39;"),
            std::string::npos);
}

TEST(HtmlPage, PassesAndInputsAreDescribed) {
  PageProject project;
  project.name = "p";
  PagePass buffer;
  buffer.tab_name = "Buffer B";
  buffer.kind = model::PassKind::kBuffer;
  buffer.output_buffer = 1;
  buffer.inputs.push_back({0, PageInputKind::kBuffer, 1, "linear", "clamp", true});
  buffer.inputs.push_back({2, PageInputKind::kKeyboard, -1, "nearest", "clamp", false});
  buffer.fragment_shader = "#version 300 es\n";
  buffer.lines = ComposedLineRuns(22, 3, 5, "Buffer B");
  project.passes.push_back(buffer);
  const nlohmann::json read = nlohmann::json::parse(PageProjectJson(project, {128}));
  EXPECT_EQ(read["cubeSize"], 128);
  const nlohmann::json& pass = read["passes"][0];
  EXPECT_EQ(pass["kind"], "buffer");
  EXPECT_EQ(pass["output"], 1);
  EXPECT_EQ(pass["inputs"][0]["kind"], "buffer");
  EXPECT_EQ(pass["inputs"][0]["buffer"], 1);
  EXPECT_EQ(pass["inputs"][1]["kind"], "keyboard");
  EXPECT_EQ(pass["inputs"][1]["filter"], "nearest");
  EXPECT_EQ(pass["inputs"][1]["vflip"], false);
  EXPECT_EQ(pass["lines"], nlohmann::json::parse(R"([[23,3,"Common",1],[26,5,"Buffer B",1]])"));
}

TEST(HtmlPage, ComposedLineRunsWithoutCommon) {
  const auto runs = ComposedLineRuns(10, 0, 4, "Image");
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].ported_first, 11u);
  EXPECT_EQ(runs[0].count, 4u);
  EXPECT_EQ(runs[0].origin, "Image");
  EXPECT_EQ(runs[0].user_first, 1u);
}

TEST(HtmlPage, LineRunsFromOrigins) {
  const std::vector<LineOrigin> lines = {
      {"", 0},      {"", 0},      {"Common", 1}, {"Common", 2}, {"Image", 1},
      {"Image", 2}, {"Image", 4}, {"", 0},       {"Image", 5},
  };
  const auto runs = LineRunsFromOrigins(lines);
  ASSERT_EQ(runs.size(), 4u);
  EXPECT_EQ(runs[0].ported_first, 3u);
  EXPECT_EQ(runs[0].count, 2u);
  EXPECT_EQ(runs[0].origin, "Common");
  EXPECT_EQ(runs[1].ported_first, 5u);
  EXPECT_EQ(runs[1].count, 2u);
  EXPECT_EQ(runs[1].user_first, 1u);
  EXPECT_EQ(runs[2].ported_first, 7u);  // a user line skipped: a new run
  EXPECT_EQ(runs[2].user_first, 4u);
  EXPECT_EQ(runs[3].ported_first, 9u);
  EXPECT_EQ(runs[3].user_first, 5u);
}

// tests/browser/project_pages/broken.json: Common (2 lines), Buffer A with an error
// on its line 3, Image reading Buffer A.
TEST(HtmlPage, PageFromPortedKeepsTabsInputsAndUserLines) {
  const std::string path =
      std::string(SHADERPORT_SOURCE_DIR) + "/tests/browser/project_pages/broken.json";
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  const ProjectDocument document = ReadShaderToyJson(text.str());
  ASSERT_EQ(document.projects.size(), 1u);
  SourceManager sources;
  const auto container = std::make_shared<const SourceFile>(kNoFile, path, text.str());
  const ProjectSources registered =
      AddProjectSources("broken.json", container, document.projects[0], 0, false, sources);
  const PageProject page = PageFromPorted(PortProject(registered, PortOptions{}, sources));
  EXPECT_EQ(page.name, "Broken Buffer A");
  ASSERT_EQ(page.passes.size(), 2u);  // Common is inlined, not a pass
  const PagePass& buffer = page.passes[0];
  EXPECT_EQ(buffer.tab_name, "Buffer A");
  EXPECT_EQ(buffer.kind, model::PassKind::kBuffer);
  EXPECT_EQ(buffer.output_buffer, 0);
  EXPECT_NE(buffer.fragment_shader.find("#version 300 es"), std::string::npos);
  // The ported line holding `undefined_name` maps to Buffer A line 3.
  const size_t at = buffer.fragment_shader.find("undefined_name");
  ASSERT_NE(at, std::string::npos);
  const auto line = static_cast<uint32_t>(
      1 + std::count(buffer.fragment_shader.begin(), buffer.fragment_shader.begin() + at, '\n'));
  bool mapped = false;
  for (const PageLineRun& run : buffer.lines) {
    if (line < run.ported_first || line >= run.ported_first + run.count) continue;
    EXPECT_EQ(run.origin, "Buffer A");
    EXPECT_EQ(run.user_first + (line - run.ported_first), 3u);
    mapped = true;
  }
  EXPECT_TRUE(mapped);
  EXPECT_TRUE(std::any_of(buffer.lines.begin(), buffer.lines.end(),
                          [](const PageLineRun& run) { return run.origin == "Common"; }));
  const PagePass& image = page.passes[1];
  EXPECT_EQ(image.kind, model::PassKind::kImage);
  ASSERT_EQ(image.inputs.size(), 1u);
  EXPECT_EQ(image.inputs[0].kind, PageInputKind::kBuffer);
  EXPECT_EQ(image.inputs[0].buffer, 0);
  EXPECT_EQ(image.inputs[0].filter, "linear");
  EXPECT_EQ(image.inputs[0].wrap, "clamp");
}

// The 1-based line of `needle` in `text`, as text.
std::string LineOf(std::string_view text, std::string_view needle) {
  const size_t at = text.find(needle);
  if (at == std::string_view::npos) return "missing";
  return std::to_string(1 + std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

// "origin:line" that the page's runs give the ported line holding `needle`.
std::string UserLineOf(const nlohmann::json& runs, const std::string& ported,
                       std::string_view needle) {
  const uint32_t line = static_cast<uint32_t>(std::stoul(LineOf(ported, needle)));
  for (const auto& run : runs) {
    const uint32_t first = run[0], count = run[1];
    if (line >= first && line < first + count)
      return run[2].get<std::string>() + ":" +
             std::to_string(run[3].get<uint32_t>() + line - first);
  }
  return "generated";
}

// The one pass of a program page, read back from its JSON.
nlohmann::json ProgramPass(const DocumentOutput& output) {
  const nlohmann::json project = nlohmann::json::parse(EmbeddedJson(output.text));
  EXPECT_EQ(project["passes"].size(), 1u);
  return project["passes"][0];
}

TEST(HtmlPage, ProgramPagesDrawAsRenderDraws) {
  const std::string ssao = std::string(SHADERPORT_SOURCE_DIR) + "/corpus/ssao/";
  SourceManager sources;
  const PortResult vertex = PortFile(ssao + "geometry.vert", PortOptions{}, sources);
  const PortResult fragment = PortFile(ssao + "position.frag", PortOptions{}, sources);
  // A pair: both ported texts, on the sphere mesh.
  const nlohmann::json pair = ProgramPass(ProgramPage(&vertex, &fragment));
  EXPECT_EQ(pair["vertex"], vertex.text);
  EXPECT_EQ(pair["code"], fragment.text);
  EXPECT_TRUE(pair["mesh"].get<bool>());
  EXPECT_NE(vertex.text.find("in vec3 Vertex"), std::string::npos) << vertex.text;
  // Ported lines map back to the user's files (errors land on them).
  EXPECT_EQ(UserLineOf(pair["lines"], fragment.text, "length(vPosition)"),
            "position.frag:" + LineOf(fragment.file->Text(), "length(vPosition)"));
  EXPECT_EQ(UserLineOf(pair["vertexLines"], vertex.text, "in vec3 Normal"),
            "geometry.vert:" + LineOf(vertex.file->Text(), "attribute vec3 Normal"));
  EXPECT_EQ(UserLineOf(pair["vertexLines"], vertex.text, "#version 300 es"), "generated");
  // A vertex shader alone gets render's depth shade.
  const nlohmann::json alone = ProgramPass(ProgramPage(&vertex, nullptr));
  EXPECT_NE(alone["code"].get<std::string>().find("gl_FragCoord.z"), std::string::npos);
  EXPECT_TRUE(alone["mesh"].get<bool>());
  // A fragment shader with an input gets render's feeder, which writes it.
  const nlohmann::json fed = ProgramPass(ProgramPage(nullptr, &fragment));
  EXPECT_FALSE(fed["mesh"].get<bool>());
  EXPECT_NE(fed["vertex"].get<std::string>().find("vPosition = "), std::string::npos)
      << fed["vertex"];
  // A stage the port could not read: the panel says why, nothing is compiled.
  PortResult unread;
  unread.read_failed = true;
  unread.diagnostics.push_back(
      MakeDiagnostic(Severity::kError, "input/unreadable", {kNoFile, 0, 0}, "cannot read it"));
  const nlohmann::json failed = ProgramPass(ProgramPage(&unread, &fragment));
  EXPECT_EQ(failed["code"], "");
  EXPECT_NE(failed["portErrors"].get<std::string>().find("cannot read it"), std::string::npos);
}

TEST(HtmlPage, RuntimeIsInlineAndLoadsNothing) {
  const std::string page = BuildProjectPage(PageProject{});
  EXPECT_NE(page.find("getContext(\"webgl2\""), std::string::npos);
  EXPECT_NE(page.find("#sp-canvas"), std::string::npos);  // the stylesheet
  EXPECT_EQ(page.find("http://"), std::string::npos);
  EXPECT_EQ(page.find("https://"), std::string::npos);
  EXPECT_EQ(page.find(" src="), std::string::npos);
  EXPECT_EQ(page.find(" href="), std::string::npos);
  EXPECT_NE(page.find("<title>ShaderToy project</title>"), std::string::npos);
  for (const page_files::EmbeddedTextFile& file : page_files::EmbeddedPageFiles()) {
    EXPECT_EQ(Lower(std::string(file.text)).find("</script"), std::string::npos) << file.name;
    EXPECT_EQ(std::string(file.text).find("<!--"), std::string::npos) << file.name;
  }
}

}  // namespace
}  // namespace shaderport::driver::project
