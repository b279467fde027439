#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "base/limits.h"
#include "driver/dialect.h"
#include "driver/input_files.h"
#include "driver/read_input.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;

class TempDir {
 public:
  TempDir()
      : path_(fs::temp_directory_path() / ("shaderport-test-" + std::to_string(::getpid()) + "-" +
                                           std::to_string(counter_++))) {
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  const fs::path& Path() const { return path_; }
  fs::path Write(const std::string& name, const std::string& text) const {
    const fs::path file = path_ / name;
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }

 private:
  static inline int counter_ = 0;
  fs::path path_;
};

TEST(CollectInputFilesTest, WalksDirectoriesForShaderExtensionsInOrder) {
  TempDir dir;
  dir.Write("b.frag", "x");
  dir.Write("a/c.vert", "x");
  dir.Write("a/readme.txt", "x");
  dir.Write(".git/d.frag", "x");
  dir.Write("z.fsh", "x");
  const InputFileList list = CollectInputFiles({dir.Path()});
  ASSERT_EQ(list.files.size(), 3u);
  EXPECT_EQ(list.files[0].filename(), "c.vert");
  EXPECT_EQ(list.files[1].filename(), "b.frag");
  EXPECT_EQ(list.files[2].filename(), "z.fsh");
  EXPECT_TRUE(list.errors.empty());
}

TEST(CollectInputFilesTest, NamedFilesAreTakenAndMissingOnesReported) {
  TempDir dir;
  const fs::path txt = dir.Write("shader.txt", "x");
  const InputFileList list = CollectInputFiles({txt, dir.Path() / "missing.frag", txt});
  ASSERT_EQ(list.files.size(), 1u);
  ASSERT_EQ(list.errors.size(), 1u);
  EXPECT_NE(list.errors[0].find("missing.frag"), std::string::npos);
}

TEST(ReadInputFileTest, RejectsEmptyBinaryAndHugeFiles) {
  TempDir dir;
  EXPECT_EQ(ReadInputFile(dir.Write("e.frag", "")).rule_id, "input/empty");
  EXPECT_EQ(ReadInputFile(dir.Write("b.frag", std::string("ab\0cd", 5))).rule_id, "input/binary");
  EXPECT_EQ(ReadInputFile(dir.Path() / "none.frag").rule_id, "input/unreadable");
  const fs::path huge = dir.Path() / "huge.frag";
  {
    std::ofstream out(huge, std::ios::binary);
    out.seekp(static_cast<std::streamoff>(limits::kMaxFileBytes) + 1);
    out.put('x');
  }
  const InputText result = ReadInputFile(huge);
  EXPECT_EQ(result.rule_id, "input/too-large");
  EXPECT_FALSE(result.text.has_value());
}

TEST(ReadInputFileTest, AcceptsTextWithInvalidUtf8InComments) {
  TempDir dir;
  const InputText result = ReadInputFile(dir.Write("ok.frag", "// caf\xe9\nvoid main(){}\n"));
  ASSERT_TRUE(result.text.has_value());
  EXPECT_EQ(result.rule_id, "");
}

TEST(DetectKindTest, VersionMainImageAndExtensionDecide) {
  EXPECT_EQ(DetectKind("#version 300 es\nvoid main(){}", "a.frag").dialect, Dialect::kWebGL2);
  EXPECT_EQ(DetectKind("void main(){ gl_FragColor = vec4(1); }", "a.frag").dialect,
            Dialect::kWebGL1);
  const DetectedKind toy = DetectKind("void mainImage(out vec4 c, in vec2 p){}", "a.glsl");
  EXPECT_EQ(toy.dialect, Dialect::kShaderToy);
  EXPECT_EQ(toy.pass, model::PassKind::kImage);
  EXPECT_EQ(toy.stage, model::Stage::kFragment);
  EXPECT_EQ(
      DetectKind("void mainCubemap(out vec4 c, in vec2 p, in vec3 o, in vec3 d){}", "c.glsl").pass,
      model::PassKind::kCube);
  EXPECT_EQ(
      DetectKind("attribute vec3 p; void main(){ gl_Position = vec4(p,1.); }", "a.glsl").stage,
      model::Stage::kVertex);
  EXPECT_EQ(DetectKind("void main(){}", "a.vs").stage, model::Stage::kVertex);
}

TEST(DetectKindTest, WordsInCommentsDoNotCount) {
  EXPECT_EQ(DetectKind("// void mainImage(out vec4 c, in vec2 p)\nvoid main(){}", "a.glsl").dialect,
            Dialect::kWebGL1);
  EXPECT_EQ(DetectKind("/* #version 300 es */ void main(){}", "a.frag").dialect, Dialect::kWebGL1);
}

}  // namespace
}  // namespace shaderport::driver
