// `check --shard K/N` and `shaderport merge` through the real binary: the shards'
// outputs, merged, are the single run's output byte for byte.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include "cli_test_util.h"

namespace shaderport::testing {
namespace {

namespace fs = std::filesystem;

class ShardMergeTest : public ::testing::Test {
 protected:
  ShardMergeTest()
      : root_(fs::temp_directory_path() /
              ("shaderport-shard-cli-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name())) {
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  ~ShardMergeTest() override { fs::remove_all(root_); }

  // Runs every shard of `paths` into files and returns them, quoted for a shell.
  std::string RunShards(const std::string& format, unsigned count, const std::string& paths,
                        const fs::path& directory) {
    std::string files;
    for (unsigned k = 1; k <= count; ++k) {
      const CommandResult shard =
          RunShaderport("check --no-cache --format " + format + " --shard " + std::to_string(k) +
                            "/" + std::to_string(count) + " " + paths,
                        directory);
      EXPECT_LE(shard.exit_code, 1) << shard.err;
      const fs::path file = root_ / (std::to_string(k) + "." + format);
      std::ofstream(file, std::ios::binary) << shard.out;
      files += " '" + file.string() + "'";
    }
    return files;
  }

  void ExpectMergeIsSingleRun(const std::string& format, unsigned count, const std::string& paths,
                              const fs::path& directory) {
    const CommandResult single =
        RunShaderport("check --no-cache --format " + format + " " + paths, directory);
    const CommandResult merged =
        RunShaderport("merge" + RunShards(format, count, paths, directory), directory);
    EXPECT_EQ(merged.err, "");
    EXPECT_EQ(merged.exit_code, single.exit_code) << format << " " << count;
    EXPECT_EQ(merged.out, single.out) << format << " " << count;
    EXPECT_FALSE(single.out.empty());
  }

  fs::path root_;
};

TEST_F(ShardMergeTest, FourShardsOfTheCorpusMergeIntoTheSingleRun) {
  for (const std::string format : {"json", "sarif"}) {
    ExpectMergeIsSingleRun(format, 4, "corpus", SourceDir());
  }
}

TEST_F(ShardMergeTest, OneShardIsTheSingleRun) {
  const CommandResult single = RunShaderport("check --no-cache --format json corpus", SourceDir());
  const CommandResult shard =
      RunShaderport("check --no-cache --format json --shard 1/1 corpus", SourceDir());
  // The same report, marked as the only shard; merge drops the marker.
  EXPECT_NE(shard.out.find("\"shard\": \"1/1\""), std::string::npos);
  std::ofstream(root_ / "only.json") << shard.out;
  EXPECT_EQ(RunShaderport("merge only.json", root_).out, single.out);
  ExpectMergeIsSingleRun("sarif", 1, "corpus", SourceDir());
}

TEST_F(ShardMergeTest, AMissingRepeatedOrForeignShardIsAUsageError) {
  for (const std::string format : {"json", "sarif"}) {
    const std::string four = RunShards(format, 4, "corpus", SourceDir());
    const std::string one = "'" + (root_ / ("1." + format)).string() + "'";
    const std::string two = "'" + (root_ / ("2." + format)).string() + "'";
    const std::string three = "'" + (root_ / ("3." + format)).string() + "'";
    // A CI job that died must not let the merged report pass.
    const CommandResult missing = RunShaderport("merge " + one + " " + two + " " + three, root_);
    EXPECT_EQ(missing.exit_code, 2) << format;
    EXPECT_NE(missing.err.find("shard 4/4 missing"), std::string::npos) << missing.err;
    EXPECT_TRUE(missing.out.empty());
    const CommandResult twice = RunShaderport("merge " + four + " " + one, root_);
    EXPECT_EQ(twice.exit_code, 2) << format;
    EXPECT_NE(twice.err.find("shard 1/4 is also in"), std::string::npos) << twice.err;
    const CommandResult other_split =
        RunShaderport("check --no-cache --format " + format + " --shard 2/3 corpus > '" +
                          (root_ / ("x." + format)).string() + "'",
                      SourceDir());
    EXPECT_LE(other_split.exit_code, 1);
    const CommandResult mixed =
        RunShaderport("merge " + one + " '" + (root_ / ("x." + format)).string() + "'", root_);
    EXPECT_EQ(mixed.exit_code, 2) << format;
    EXPECT_NE(mixed.err.find("is not one of 4 shards"), std::string::npos) << mixed.err;
  }
}

TEST_F(ShardMergeTest, EveryFileIsInOneShardAndProgramsStayTogether) {
  std::map<std::string, int> shard_of;
  for (unsigned k = 1; k <= 4; ++k) {
    const CommandResult shard = RunShaderport(
        "check --no-cache --format json --shard " + std::to_string(k) + "/4 corpus", SourceDir());
    for (size_t at = shard.out.find("\n      \"path\": \""); at != std::string::npos;
         at = shard.out.find("\n      \"path\": \"", at + 1)) {
      const size_t begin = at + 16;
      const std::string path = shard.out.substr(begin, shard.out.find('"', begin) - begin);
      EXPECT_FALSE(shard_of.contains(path)) << path;
      shard_of[path] = static_cast<int>(k);
    }
  }
  EXPECT_EQ(shard_of.size(), 41u);
  EXPECT_EQ(shard_of.at("corpus/ssao/lighting.vert"), shard_of.at("corpus/ssao/lighting.frag"));
}

TEST_F(ShardMergeTest, AShardWithNoFilesMergesToo) {
  // One file and two shards: one of them is empty.
  const fs::path project = root_ / "one";
  fs::create_directories(project);
  fs::copy(SourceDir() / "corpus/ao/template.glsl", project / "template.glsl");
  int empty_shards = 0;
  for (unsigned k = 1; k <= 2; ++k) {
    const CommandResult shard = RunShaderport(
        "check --no-cache --format json --shard " + std::to_string(k) + "/2 .", project);
    empty_shards += shard.out.find("\"files\": []") != std::string::npos;
  }
  EXPECT_EQ(empty_shards, 1);
  for (const std::string format : {"json", "sarif"})
    ExpectMergeIsSingleRun(format, 2, ".", project);
}

TEST_F(ShardMergeTest, ShaderToyPassesStayWithTheirCommon) {
  // Common's own findings are reported once, on Common, in the single run; a pass
  // on another shard would report them again.
  const fs::path project = root_ / "toys";
  for (int d = 0; d < 6; ++d) {
    const fs::path dir = project / ("toy" + std::to_string(d));
    fs::create_directories(dir);
    std::ofstream(dir / "common.glsl") << "float helper() { return 1; }\n";
    for (int p = 0; p < 3; ++p) {
      std::ofstream(dir / ("pass" + std::to_string(p) + ".glsl"))
          << "void mainImage(out vec4 c, in vec2 f) { c = vec4(helper() * " << p << "); }\n";
    }
  }
  for (const std::string format : {"json", "sarif"}) {
    ExpectMergeIsSingleRun(format, 4, ".", project);
  }
  // The same with Common given once for all passes (spread over the shards).
  ExpectMergeIsSingleRun("sarif", 3, "--common toy0/common.glsl toy1 toy2", project);
  ExpectMergeIsSingleRun("json", 3, "--common toy0/common.glsl toy1/pass0.glsl toy2", project);
}

TEST_F(ShardMergeTest, BadShardSpecsAreUsageErrors) {
  for (const std::string spec : {"0/4", "5/4", "1/0", "x", "1/2/3", "-1/2"}) {
    const CommandResult run =
        RunShaderport("check --no-cache --shard " + spec + " corpus", SourceDir());
    EXPECT_EQ(run.exit_code, 2) << spec;
    EXPECT_NE(run.err.find("--shard"), std::string::npos) << run.err;
    EXPECT_EQ(run.out, "");
  }
}

TEST_F(ShardMergeTest, MixedFormatsVersionsAndJunkAreUsageErrors) {
  const CommandResult json = RunShaderport("check --no-cache --format json corpus/ao", SourceDir());
  const CommandResult sarif =
      RunShaderport("check --no-cache --format sarif corpus/ao", SourceDir());
  const fs::path json_file = root_ / "a.json";
  const fs::path sarif_file = root_ / "a.sarif";
  const fs::path other_version = root_ / "b.json";
  const fs::path junk = root_ / "junk.json";
  std::ofstream(json_file) << json.out;
  std::ofstream(sarif_file) << sarif.out;
  std::string renamed = json.out;
  renamed.replace(renamed.find("\"version\": \"") + 12, 1, "9");
  std::ofstream(other_version) << renamed;
  std::ofstream(junk) << "not json at all";
  auto merge = [&](const std::string& args) { return RunShaderport("merge " + args, root_); };
  EXPECT_EQ(merge("a.json a.sarif").exit_code, 2);
  EXPECT_NE(merge("a.json a.sarif").err.find("a.sarif"), std::string::npos);
  EXPECT_EQ(merge("a.json b.json").exit_code, 2);
  EXPECT_EQ(merge("a.json junk.json").exit_code, 2);
  EXPECT_EQ(merge("--format sarif a.json").exit_code, 2);
  EXPECT_EQ(merge("no-such-file.json").exit_code, 2);
  EXPECT_EQ(merge("").exit_code, 2);
  // corpus/ao has errors: merge fails on them like check.
  EXPECT_EQ(merge("a.json").exit_code, 1);
  EXPECT_EQ(merge("a.json").out, json.out);
  EXPECT_EQ(merge("--format json a.json a.json").out, json.out);
}

TEST_F(ShardMergeTest, ExitCodeFollowsFailOn) {
  const fs::path project = root_ / "warn";
  fs::create_directories(project);
  // Only a warning: no precision statement, made a warning by the config.
  fs::copy(SourceDir() / "tests/data/check-project/webgl2/no-precision.frag",
           project / "no-precision.frag");
  std::ofstream(project / ".shaderport.toml")
      << "[rules]\n\"glslang/missing-precision\" = \"warning\"\n";
  const CommandResult check = RunShaderport("check --no-cache --format json .", project);
  ASSERT_EQ(check.exit_code, 0) << check.out;
  ASSERT_NE(check.out.find("\"severity\": \"warning\""), std::string::npos) << check.out;
  std::ofstream(root_ / "w.json") << check.out;
  EXPECT_EQ(RunShaderport("merge w.json", root_).exit_code, 0);
  EXPECT_EQ(RunShaderport("merge --fail-on warning w.json", root_).exit_code, 1);
  EXPECT_EQ(RunShaderport("merge --fail-on bogus w.json", root_).exit_code, 2);
}

}  // namespace
}  // namespace shaderport::testing
