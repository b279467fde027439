// The port changes nothing a viewer can see: the picture the site composition of a
// ShaderToy pass renders, the picture of its `port` output drawn as a plain WebGL2
// shader, and the picture of the ESSL round trip (SPIR-V and back) of that output are
// equal within docs/render.md's tolerance. 64x64, hermetic renders.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "driver/html_report/render_ported.h"
#include "driver/port/port_file.h"
#include "driver/render_check/render_file.h"
#include "toolchain/emit.h"

namespace shaderport::driver {
namespace {

namespace fs = std::filesystem;

// docs/render.md: every channel within 8, at most 1 % of pixels off by more than 2.
testing::AssertionResult WithinTolerance(const render::ImageRgba8& a, const render::ImageRgba8& b) {
  if (a.width != b.width || a.height != b.height || a.pixels.size() != b.pixels.size()) {
    return testing::AssertionFailure() << "sizes differ";
  }
  size_t off_by_more_than_2 = 0;
  int worst = 0;
  for (size_t p = 0; p < a.pixels.size(); p += 4) {
    int pixel_worst = 0;
    for (size_t c = 0; c < 4; ++c) {
      pixel_worst = std::max(pixel_worst, std::abs(int{a.pixels[p + c]} - int{b.pixels[p + c]}));
    }
    worst = std::max(worst, pixel_worst);
    if (pixel_worst > 2) ++off_by_more_than_2;
  }
  const size_t pixels = a.pixels.size() / 4;
  if (worst > 8 || off_by_more_than_2 * 100 > pixels) {
    return testing::AssertionFailure()
           << "largest channel difference " << worst << ", " << off_by_more_than_2 << " of "
           << pixels << " pixels off by more than 2";
  }
  return testing::AssertionSuccess();
}

RenderFileOptions Options() {
  RenderFileOptions options;
  options.base.width = 64;
  options.base.height = 64;
  options.render.hermetic = true;
  return options;
}

// Site composition, port, round trip: three pictures of one ShaderToy pass.
void ExpectSamePictures(const fs::path& path) {
  SCOPED_TRACE(path.string());
  SourceManager sources;
  PortResult ported = PortFile(path, PortOptions{}, sources);
  ASSERT_TRUE(ported.validated) << "the port does not validate";

  RenderFileOptions options = Options();
  // The port may declare a channel as a cube or 3D sampler; the site composition
  // must bind the same kind of texture.
  options.channel_types = ChannelTypesOf(ported.text);
  const RenderFileResult site = RenderFile(path, sources, options);
  ASSERT_TRUE(site.image.has_value()) << "the site composition did not render";
  ASSERT_FALSE(HasErrors(site.diagnostics));

  const RenderFileResult port = RenderPortResult(ported, Options());
  ASSERT_TRUE(port.image.has_value()) << "the port did not render";
  EXPECT_FALSE(HasErrors(port.diagnostics));
  EXPECT_TRUE(WithinTolerance(site.image.value(), port.image.value())) << "site vs port";

  const SourceFile& ported_file = sources.Add(path.string() + "#port", ported.text);
  toolchain::EmitOptions emit;
  emit.kind = toolchain::EmitKind::kEsslRoundtrip;
  const toolchain::EmitResult roundtrip =
      toolchain::Emit(ported_file, model::Stage::kFragment, emit);
  ASSERT_FALSE(HasErrors(roundtrip.diagnostics)) << "the round trip failed";
  PreparedShader shader;
  shader.fragment_text = roundtrip.output;
  shader.anchor = SourceRange{ported_file.Id(), 0, 0};
  RenderFileOptions roundtrip_options = Options();
  roundtrip_options.channel_types = ChannelTypesOf(roundtrip.output);
  RenderFileResult again;
  RenderPrepared(shader, roundtrip_options, again);
  ASSERT_TRUE(again.image.has_value()) << "the round trip did not render";
  EXPECT_FALSE(HasErrors(again.diagnostics));
  EXPECT_TRUE(WithinTolerance(port.image.value(), again.image.value())) << "port vs round trip";
}

TEST(RenderEqualityTolerance, AcceptsSmallAndRejectsLargeDifferences) {
  render::ImageRgba8 a;
  a.width = 10;
  a.height = 10;
  a.pixels.assign(400, 100);
  render::ImageRgba8 b = a;
  b.pixels[0] = 108;  // one pixel off by 8: within
  EXPECT_TRUE(WithinTolerance(a, b));
  b.pixels[0] = 109;  // off by 9: not
  EXPECT_FALSE(WithinTolerance(a, b));
  b.pixels[0] = 103;
  b.pixels[4] = 103;  // 2 % of pixels off by 3: not
  EXPECT_FALSE(WithinTolerance(a, b));
}

TEST(RenderEquality, CorpusShaderToyPassesAndControls) {
  const fs::path corpus = fs::path(SHADERPORT_SOURCE_DIR) / "corpus";
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(corpus / "ao")) {
    if (entry.path().filename() != "steps-1-5.glsl") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_EQ(files.size(), 7u);
  files.push_back(corpus / "strict-typing/control-explicit-conversions.glsl");
  files.push_back(corpus / "strict-typing/control-explicit-conversions.frag");
  for (const fs::path& file : files) ExpectSamePictures(file);
}

// Five single-pass Image shaders without inputs from the shared corpus, fixed by id:
// the first by id whose port validates and whose render takes well under a second.
TEST(RenderEquality, SharedCorpusPasses) {
  const std::vector<std::string> ids = {"3dVfz1", "3lGXRc", "3ltSW2", "3tfXWN", "4sGfWy"};
  std::ifstream in(fs::path(SHADERPORT_SHARED_DIR) / "corpus-shadertoy/permissive.jsonl");
  if (!in) GTEST_SKIP() << "shared ShaderToy corpus not available";
  const fs::path dir =
      fs::path(::testing::TempDir()) / ("shaderport-render-equality-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  size_t found = 0;
  std::string line;
  while (std::getline(in, line)) {
    for (const std::string& id : ids) {
      if (line.find("\"id\": \"" + id + "\"") == std::string::npos) continue;
      const nlohmann::json shader = nlohmann::json::parse(line);
      ASSERT_EQ(shader["id"], id);
      for (const auto& pass : shader["passes"]) {
        if (pass["type"] != "image") continue;
        const fs::path path = dir / (id + ".glsl");
        std::ofstream(path) << pass["code"].get<std::string>();
        ExpectSamePictures(path);
        ++found;
      }
    }
  }
  fs::remove_all(dir);
  EXPECT_EQ(found, ids.size());
}

}  // namespace
}  // namespace shaderport::driver
