// Golden PNG comparison for render tests. Tolerance (docs/render.md): every channel
// of every pixel within 8 of the golden, and at most 1% of pixels off by more than 2.
// SHADERPORT_UPDATE_GOLDENS=1 rewrites the goldens instead of comparing.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "golden.h"
#include "render/png_io.h"

namespace shaderport::render::testing {

inline std::string GoldenPath(const std::string& name) {
  return std::string(SHADERPORT_SOURCE_DIR) + "/tests/golden/render/" + name + ".png";
}

using shaderport::testing::UpdatingGoldens;

inline ::testing::AssertionResult MatchesWithinTolerance(const ImageRgba8& actual,
                                                         const ImageRgba8& golden) {
  if (actual.width != golden.width || actual.height != golden.height) {
    return ::testing::AssertionFailure() << "size differs from the golden";
  }
  int max_diff = 0;
  size_t off_pixels = 0;
  for (size_t i = 0; i < actual.pixels.size(); i += 4) {
    int pixel_diff = 0;
    for (size_t c = 0; c < 4; ++c) {
      pixel_diff = std::max(pixel_diff, std::abs(int{actual.pixels[i + c]} - golden.pixels[i + c]));
    }
    max_diff = std::max(max_diff, pixel_diff);
    if (pixel_diff > 2) ++off_pixels;
  }
  const size_t pixels = actual.pixels.size() / 4;
  if (max_diff > 8 || off_pixels * 100 > pixels) {
    return ::testing::AssertionFailure()
           << "max channel difference " << max_diff << ", " << off_pixels << " of " << pixels
           << " pixels differ by more than 2";
  }
  return ::testing::AssertionSuccess();
}

// Compares with (or, when updating, writes) tests/golden/render/<name>.png.
inline void ExpectMatchesGolden(const ImageRgba8& image, const std::string& name) {
  std::string error;
  const std::string path = GoldenPath(name);
  if (UpdatingGoldens()) {
    const std::string png = EncodePng(image);
    ASSERT_FALSE(png.empty());
    std::ofstream(path, std::ios::binary) << png;
    return;
  }
  ImageRgba8 golden;
  ASSERT_TRUE(ReadPng(path, golden, error)) << error << " (run with SHADERPORT_UPDATE_GOLDENS=1)";
  EXPECT_TRUE(MatchesWithinTolerance(image, golden)) << name;
}

}  // namespace shaderport::render::testing
