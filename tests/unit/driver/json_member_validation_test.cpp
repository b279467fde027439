// Members of ShaderToy JSON documents of the wrong type, out of range, missing or of
// the wrong shape: each a problem at the member, never an exception, for the project
// reader (check, fix, port, report) and the multipass renderer's reader.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "../../fuzz/json_mutations.h"
#include "driver/project/json_project_reader.h"
#include "driver/render_check/render_multipass.h"
#include "golden.h"

namespace shaderport::driver::project {
namespace {

constexpr const char* kExport =
    R"({"Shader":{"info":{"id":"x","name":"n"},"renderpass":[{"type":"image","name":"Image",)"
    R"("code":"void mainImage(out vec4 c, in vec2 p){c=vec4(1);}",)"
    R"("inputs":[{"channel":"0","ctype":"buffer"}]}]}})";

TEST(JsonMemberValidation, ChannelOfTheWrongTypeIsAProblemAtTheMember) {
  const std::string text = kExport;
  const ProjectDocument read = ReadShaderToyJson(text);
  ASSERT_EQ(read.problems.size(), 1u);
  EXPECT_EQ(read.problems[0].offset, text.find("\"0\""));
  EXPECT_EQ(read.problems[0].message,
            "\"channel\" at /Shader/renderpass/0/inputs/0/channel must be an integer from 0 to 3, "
            "not a string");
}

TEST(JsonMemberValidation, RangeAndPresenceAreChecked) {
  std::string text = kExport;
  text.replace(text.find("\"0\""), 3, "7");
  ProjectDocument read = ReadShaderToyJson(text);
  ASSERT_EQ(read.problems.size(), 1u);
  EXPECT_NE(read.problems[0].message.find("not the integer 7"), std::string::npos);
  EXPECT_EQ(read.problems[0].offset, text.find("7"));

  text = kExport;
  text.replace(text.find("\"channel\":\"0\","), 14, "");
  read = ReadShaderToyJson(text);
  ASSERT_EQ(read.problems.size(), 1u);
  EXPECT_NE(read.problems[0].message.find("missing member \"channel\""), std::string::npos);
  EXPECT_EQ(read.problems[0].offset, text.find("{\"ctype\""));  // the input object
}

TEST(JsonMemberValidation, TheMembersProblemComesBeforeWhatFollowsFromIt) {
  std::string text = kExport;
  text.replace(text.find("\"0\""), 3, "0");
  text.replace(text.find("\"image\""), 7, "0");  // no Image pass follows from this
  const ProjectDocument read = ReadShaderToyJson(text);
  ASSERT_EQ(read.problems.size(), 2u);
  EXPECT_NE(read.problems[0].message.find("\"type\" at /Shader/renderpass/0/type must be a "
                                          "string, not the integer 0"),
            std::string::npos)
      << read.problems[0].message;
  EXPECT_NE(read.problems[1].message.find("no Image pass"), std::string::npos);
}

TEST(JsonMemberValidation, EachDocumentOfAJsonLinesFileKeepsItsOwnProblems) {
  std::string good = kExport;
  good.replace(good.find("\"0\""), 3, "0");
  const std::string text = std::string(kExport) + "\n" + good + "\n";
  const ProjectDocument read = ReadShaderToyJsonLines(text);
  EXPECT_EQ(read.projects.size(), 2u);  // the second line is still read
  ASSERT_EQ(read.problems.size(), 1u);
  EXPECT_LT(read.problems[0].offset, good.size());
}

TEST(JsonMemberValidation, RenderReaderReportsInsteadOfThrowing) {
  SourceManager sources;
  RenderFileOptions options;
  const RenderFileResult result = RenderShaderToyJson("p.json", kExport, sources, options);
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].rule_id, "input/invalid-project");
  EXPECT_FALSE(result.image);
}

// Every type swap, removal and wrong shape of every value of the shipped examples:
// no exception, and every problem offset inside the document.
TEST(JsonMemberValidation, NoMutationOfTheShippedExamplesThrows) {
  size_t runs = 0;
  size_t with_problems = 0;
  for (const char* seed : {"multipass.json", "api-export.json", "image-only.json"}) {
    const nlohmann::json document = nlohmann::json::parse(testing::ReadWholeFile(
        std::filesystem::path(SHADERPORT_SOURCE_DIR) / "tests/fuzz/seeds/shadertoy_json" / seed));
    for (const auto& at : fuzz::AllPointers(document)) {
      for (const auto mutation : {fuzz::JsonMutation::kTypeSwap, fuzz::JsonMutation::kRemoveMember,
                                  fuzz::JsonMutation::kWrongShape}) {
        const size_t variants = mutation == fuzz::JsonMutation::kTypeSwap
                                    ? fuzz::TypeSwaps(document[at]).size()
                                : mutation == fuzz::JsonMutation::kWrongShape ? 2
                                                                              : 1;
        for (size_t variant = 0; variant < variants; ++variant) {
          nlohmann::json mutated = document;
          if (!fuzz::MutateAt(mutated, at, mutation, variant)) continue;
          const std::string text = mutated.dump();
          ++runs;
          ProjectDocument read;
          ASSERT_NO_THROW(read = ReadShaderToyJson(text)) << seed << " " << at.to_string();
          with_problems += read.problems.empty() ? 0 : 1;
          for (const ProjectProblem& problem : read.problems) {
            EXPECT_LE(problem.offset, text.size()) << seed << " " << at.to_string();
          }
          ASSERT_NO_THROW(ReadShaderToyJsonLines(text));
        }
      }
    }
  }
  EXPECT_GT(runs, 300u);
  EXPECT_GT(with_problems, runs / 4);
  std::printf("%zu mutated documents, %zu with problems, none threw\n", runs, with_problems);
}

// Several mutations stacked (what the fuzz targets' custom mutator does over many
// rounds), seeded: no exception from either reader, offsets inside the document.
TEST(JsonMemberValidation, StackedRandomMutationsNeverThrow) {
  const nlohmann::json seed = nlohmann::json::parse(
      testing::ReadWholeFile(std::filesystem::path(SHADERPORT_SOURCE_DIR) /
                             "tests/fuzz/seeds/shadertoy_json/api-export.json"));
  std::mt19937_64 random(31);
  for (int round = 0; round < 2000; ++round) {
    nlohmann::json document = seed;
    const int steps = 1 + static_cast<int>(random() % 4);
    for (int step = 0; step < steps; ++step) document = fuzz::MutateJson(document, random);
    const std::string text = document.dump();
    ProjectDocument read;
    ASSERT_NO_THROW(read = ReadShaderToyJson(text)) << text;
    for (const ProjectProblem& problem : read.problems) ASSERT_LE(problem.offset, text.size());
    SourceManager sources;
    RenderFileOptions options;
    options.channel_images[0] = "/nonexistent/stops-before-render.png";
    if (read.problems.empty()) continue;  // a valid one would be drawn
    ASSERT_NO_THROW(RenderShaderToyJson("m.json", text, sources, options)) << text;
  }
}

}  // namespace
}  // namespace shaderport::driver::project
