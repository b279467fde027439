// Golden files for every test executable: compared byte for byte, rewritten
// only when SHADERPORT_UPDATE_GOLDENS=1 is set (then review the diff), never by hand.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace shaderport::testing {

inline std::string ReadWholeFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

inline bool UpdatingGoldens() {
  const char* update = std::getenv("SHADERPORT_UPDATE_GOLDENS");
  return update != nullptr && std::string(update) == "1";
}

// Compares `actual` with the golden file, or rewrites the file when updating.
inline ::testing::AssertionResult MatchesGolden(const std::string& actual,
                                                const std::filesystem::path& golden) {
  if (UpdatingGoldens()) {
    std::filesystem::create_directories(golden.parent_path());
    std::ofstream(golden, std::ios::binary) << actual;
    return ::testing::AssertionSuccess();
  }
  if (!std::filesystem::exists(golden)) {
    return ::testing::AssertionFailure()
           << golden << " is missing; run with SHADERPORT_UPDATE_GOLDENS=1 and review it";
  }
  if (ReadWholeFile(golden) == actual) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "output differs from " << golden << "\n--- actual ---\n"
                                       << actual;
}

}  // namespace shaderport::testing
