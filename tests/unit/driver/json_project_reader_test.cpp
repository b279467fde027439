#include "driver/project/json_project_reader.h"

#include <gtest/gtest.h>

#include "driver/project/record_json.h"

namespace shaderport::driver::project {
namespace {

// The site's API export (v0.1: inputs name `type` and `filepath`, outputs carry ids).
constexpr const char* kApiExport = R"({"Shader": {"ver": "0.1",
 "info": {"id": "abc123", "name": "Feedback", "username": "someone", "description": "d"},
 "renderpass": [
  {"inputs": [{"id": "4dXGR8", "filepath": "/media/previz/buffer00.png", "type": "buffer",
               "channel": 0, "sampler": {"filter": "linear", "wrap": "clamp", "vflip": "true",
               "srgb": "false", "internal": "byte"}, "published": 1}],
   "outputs": [{"id": "4dfGRr", "channel": 0}], "code": "void mainImage(out vec4 c, in vec2 p) { c = texture(iChannel0, p); }",
   "name": "Image", "description": "", "type": "image"},
  {"inputs": [{"id": "4dXGR8", "type": "buffer", "channel": 1},
              {"id": 33, "type": "keyboard", "channel": 2},
              {"id": 41, "type": "cubemap", "channel": 3}],
   "outputs": [{"id": "4dXGR8", "channel": 0}], "code": "void mainImage(out vec4 c, in vec2 p) { c = vec4(1); }",
   "name": "Buf", "type": "buffer"},
  {"inputs": [], "outputs": [], "code": "float k() { return 1.0; }", "name": "Common", "type": "common"}
 ]}})";

TEST(JsonProjectReader, ReadsTheSiteExportWithItsTabsOutputsAndChannels) {
  const ProjectDocument read = ReadShaderToyJson(kApiExport);
  ASSERT_TRUE(read.problems.empty()) << read.problems[0].message;
  ASSERT_EQ(read.projects.size(), 1u);
  const ShaderToyProject& project = read.projects[0];
  EXPECT_EQ(project.format, ProjectFormat::kApiExport);
  EXPECT_EQ(project.id, "abc123");
  EXPECT_EQ(project.author, "someone");
  ASSERT_EQ(project.passes.size(), 3u);
  const ProjectPass& buffer = project.passes[1];
  EXPECT_EQ(buffer.kind, model::PassKind::kBuffer);
  EXPECT_EQ(buffer.output_buffer, 0);  // from the output id, whatever the tab is called
  ASSERT_EQ(buffer.inputs.size(), 3u);
  EXPECT_EQ(buffer.inputs[0].source, ChannelSource::kBuffer);
  EXPECT_EQ(buffer.inputs[0].buffer, 0);  // by id: no filepath given
  EXPECT_EQ(buffer.inputs[1].source, ChannelSource::kKeyboard);
  EXPECT_EQ(buffer.inputs[2].source, ChannelSource::kCubeBuffer);  // id 41: Cube A
  const ProjectPass& image = project.passes[0];
  EXPECT_EQ(image.inputs[0].sampler.filter, "linear");
  EXPECT_EQ(image.inputs[0].sampler.wrap, "clamp");
  EXPECT_NE(project.Common(), nullptr);
  // Every code byte maps to the byte of the document it was read from.
  const std::string document = kApiExport;
  for (size_t i = 0; i < image.code.size(); ++i)
    EXPECT_EQ(document[image.origin.document_offsets[i]], image.code[i]);
}

TEST(JsonProjectReader, ReadsListsBareExportsAndCorpusRecordsAndJsonLines) {
  const std::string bare =
      R"({"info": {"id": "x"}, "renderpass": [{"type": "image", "code": "a"}]})";
  EXPECT_EQ(ReadShaderToyJson("[" + bare + ", " + bare + "]").projects.size(), 2u);
  const std::string record =
      R"({"id": "r1", "license": "mit", "passes": [{"type": "image", "name": "Image", "code": "b"},)"
      R"( {"type": "buffer", "name": "Buffer C", "code": "c"}, {"type": "cube", "name": "Cube A", "code": "d"}]})";
  const ProjectDocument one = ReadShaderToyJson(record);
  ASSERT_EQ(one.projects.size(), 1u);
  EXPECT_EQ(one.projects[0].format, ProjectFormat::kCorpusRecord);
  EXPECT_EQ(one.projects[0].license, "mit");
  EXPECT_EQ(one.projects[0].passes[1].output_buffer, 2);
  EXPECT_EQ(one.projects[0].passes[2].kind, model::PassKind::kCube);
  const std::string lines = record + "\n\n" + record + "\n";
  const ProjectDocument many = ReadShaderToyJsonLines(lines);
  ASSERT_EQ(many.projects.size(), 2u);
  // Offsets stay offsets of the whole file.
  const uint32_t second = many.projects[1].passes[0].origin.document_offsets[0];
  EXPECT_EQ(lines[second], 'b');
  EXPECT_GT(second, record.size());
}

// The 8 MiB limit is per project: one line past it is left out with a problem at that
// line, and the lines around it are read.
TEST(JsonProjectReader, ALineOverTheProjectLimitIsLeftOutAlone) {
  const std::string record =
      R"({"id": "r1", "passes": [{"type": "image", "name": "Image", "code": "b"}]})";
  const std::string huge =
      R"({"id": "big", "passes": [{"type": "image", "name": "Image", "code": ")" +
      std::string(9u << 20, 'x') + R"("}]})";
  const std::string lines = record + "\n" + huge + "\n" + record + "\n";
  const ProjectDocument read = ReadShaderToyJsonLines(lines);
  EXPECT_EQ(read.projects.size(), 2u);
  ASSERT_EQ(read.problems.size(), 1u);
  EXPECT_EQ(read.problems[0].offset, record.size() + 1);
  EXPECT_NE(read.problems[0].message.find("9.1 MiB, larger than the 8 MiB limit of one project"),
            std::string::npos)
      << read.problems[0].message;
}

TEST(JsonProjectReader, ReportsWhatIsWrongAndWhere) {
  const ProjectDocument broken = ReadShaderToyJson("{\"Shader\": {\"renderpass\": [}");
  ASSERT_EQ(broken.problems.size(), 1u);
  EXPECT_NE(broken.problems[0].message.find("invalid JSON"), std::string::npos);
  EXPECT_EQ(broken.problems[0].offset, 27u);
  const ProjectDocument unknown = ReadShaderToyJson(
      R"({"renderpass": [{"type": "image", "code": "a"}, {"type": "video", "code": ""}]})");
  ASSERT_EQ(unknown.problems.size(), 1u);
  EXPECT_NE(unknown.problems[0].message.find("unknown pass type \"video\""), std::string::npos);
  const ProjectDocument twice = ReadShaderToyJson(
      R"({"renderpass": [{"type": "image", "code": "a"}, {"type": "image", "code": "b"}]})");
  ASSERT_EQ(twice.problems.size(), 1u);
  EXPECT_NE(twice.problems[0].message.find("a second \"Image\""), std::string::npos);
  const ProjectDocument no_output = ReadShaderToyJson(
      R"({"renderpass": [{"type": "image", "code": "a"}, {"type": "buffer", "name": "Mine", "code": "a"}]})");
  ASSERT_EQ(no_output.problems.size(), 1u);
  EXPECT_TRUE(ReadShaderToyJson(R"({"name": "package.json"})").projects.empty());
  // Found by fuzz_project_json: the JSON library throws out_of_range for this number.
  const ProjectDocument overflow = ReadShaderToyJson(R"({"renderpass": [], "x": 1e99999})");
  ASSERT_EQ(overflow.problems.size(), 1u);
  EXPECT_NE(overflow.problems[0].message.find("number overflow"), std::string::npos);
  const ProjectDocument no_image =
      ReadShaderToyJson(R"({"renderpass": [{"type": "common", "code": "float k;"}]})");
  ASSERT_EQ(no_image.problems.size(), 1u);
  EXPECT_NE(no_image.problems[0].message.find("no Image pass"), std::string::npos);
  // Deep nesting is refused before parsing.
  const ProjectDocument deep =
      ReadShaderToyJson(std::string(100000, '[') + std::string(100000, ']'));
  ASSERT_EQ(deep.problems.size(), 1u);
  EXPECT_NE(deep.problems[0].message.find("nested deeper"), std::string::npos);
}

TEST(JsonProjectReader, RecordJsonReadsBackAsTheSameProject) {
  const ProjectDocument read = ReadShaderToyJson(kApiExport);
  const ProjectDocument again = ReadShaderToyJson(ToRecordJson(read.projects.at(0)));
  ASSERT_TRUE(again.problems.empty());
  const ShaderToyProject& a = read.projects[0];
  const ShaderToyProject& b = again.projects.at(0);
  ASSERT_EQ(a.passes.size(), b.passes.size());
  for (size_t i = 0; i < a.passes.size(); ++i) {
    EXPECT_EQ(a.passes[i].code, b.passes[i].code);
    EXPECT_EQ(a.passes[i].kind, b.passes[i].kind);
    EXPECT_EQ(a.passes[i].output_buffer, b.passes[i].output_buffer);
    ASSERT_EQ(a.passes[i].inputs.size(), b.passes[i].inputs.size());
    for (size_t c = 0; c < a.passes[i].inputs.size(); ++c) {
      EXPECT_EQ(a.passes[i].inputs[c].source, b.passes[i].inputs[c].source);
      EXPECT_EQ(a.passes[i].inputs[c].buffer, b.passes[i].inputs[c].buffer);
    }
  }
}

}  // namespace
}  // namespace shaderport::driver::project
