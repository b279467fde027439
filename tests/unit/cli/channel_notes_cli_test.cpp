// When a channel's sampler type explains glslang's errors, check says so: the errors
// of a sampling that does not fit the channel's type get a note naming the channel,
// where its type came from and the option that changes it.
#include <gtest/gtest.h>

#include <string>

#include "cli/cli_test_util.h"
#include "cli/temp_project.h"

namespace shaderport::testing {
namespace {

TEST(ChannelNotesCli, AChannelGivenAs2DButSampledAsACubeMapIsNamed) {
  TempProject project("channel-notes");
  project.Write(
      "cube.glsl",
      "void mainImage(out vec4 o, in vec2 p) { o = texture(iChannel0, vec3(p, 1.0)); }\n");
  // Inferred: a cube map, no error.
  EXPECT_EQ(RunShaderport("check cube.glsl", project.Root()).exit_code, 0);
  const CommandResult forced = RunShaderport("check --channel 0=2d cube.glsl", project.Root());
  EXPECT_EQ(forced.exit_code, 1);
  EXPECT_NE(forced.out.find("note: iChannel0 is a 2d texture here (given by --channel), and this "
                            "samples it with a 3-component coordinate"),
            std::string::npos)
      << forced.out;
  EXPECT_NE(forced.out.find("give it as --channel 0=cube"), std::string::npos);
}

TEST(ChannelNotesCli, ACubeMapSampledWith2DCoordinatesIsNamed) {
  TempProject project("channel-notes-2d");
  project.Write("flat.glsl",
                "void mainImage(out vec4 o, in vec2 p) { o = texture(iChannel1, p); }\n");
  const CommandResult forced = RunShaderport("check --channel 1=cube flat.glsl", project.Root());
  EXPECT_EQ(forced.exit_code, 1);
  EXPECT_NE(forced.out.find("note: iChannel1 is a cube texture here (given by --channel), and "
                            "this samples it with a 2-component coordinate"),
            std::string::npos)
      << forced.out;
  // An error that has nothing to do with a channel gets no such note.
  project.Write("other.glsl", "void mainImage(out vec4 o, in vec2 p) { o = vec4(q); }\n");
  EXPECT_EQ(RunShaderport("check other.glsl", project.Root()).out.find("texture here"),
            std::string::npos);
}

}  // namespace
}  // namespace shaderport::testing
