// Every model value has a name its parse function reads back, and the spellings the
// command line, reports and ShaderToy exports use stay as they are.
#include <gtest/gtest.h>

#include "model/channel_kind.h"
#include "model/pass_kind.h"
#include "model/stage.h"
#include "model/target.h"

namespace shaderport::model {
namespace {

TEST(ModelNames, StageRoundTrips) {
  for (Stage stage : {Stage::kVertex, Stage::kFragment}) {
    EXPECT_EQ(ParseStage(StageName(stage)), stage);
  }
  EXPECT_EQ(StageName(Stage::kVertex), "vertex");
  EXPECT_EQ(ParseStage("frag"), Stage::kFragment);
  EXPECT_EQ(ParseStage("Vertex"), std::nullopt);
}

TEST(ModelNames, TargetRoundTrips) {
  for (Target target : {Target::kWebGL1, Target::kWebGL2}) {
    EXPECT_EQ(ParseTarget(TargetName(target)), target);
  }
  EXPECT_EQ(TargetName(Target::kWebGL2), "webgl2");
  EXPECT_EQ(ParseTarget("webgl3"), std::nullopt);
}

TEST(ModelNames, ChannelKindRoundTrips) {
  for (ChannelKind kind : {ChannelKind::k2D, ChannelKind::kCube, ChannelKind::k3D}) {
    EXPECT_EQ(ParseChannelKind(ChannelKindName(kind)), kind);
  }
  EXPECT_EQ(ChannelKindName(ChannelKind::kCube), "cube");
  EXPECT_EQ(ParseChannelKind("auto"), std::nullopt);
  EXPECT_EQ(SamplerTypeName(ChannelKind::k3D), "sampler3D");
  EXPECT_EQ(ChannelKindFromCtype("cubemap"), ChannelKind::kCube);
  EXPECT_EQ(ChannelKindFromCtype("volume"), ChannelKind::k3D);
  EXPECT_EQ(ChannelKindFromCtype("keyboard"), ChannelKind::k2D);
}

TEST(ModelNames, PassKindRoundTrips) {
  for (PassKind kind : {PassKind::kImage, PassKind::kBuffer, PassKind::kCube, PassKind::kSound,
                        PassKind::kCommon}) {
    EXPECT_EQ(ParsePassKind(PassKindName(kind)), kind);
  }
  EXPECT_EQ(PassKindName(PassKind::kCube), "cube");
  EXPECT_EQ(ParsePassKind("cubemap"), std::nullopt);
}

}  // namespace
}  // namespace shaderport::model
