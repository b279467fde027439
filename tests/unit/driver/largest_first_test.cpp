#include "driver/largest_first.h"

#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <vector>

#include "driver/parallel_for.h"
#include "driver/read_input.h"

namespace shaderport::driver {
namespace {

TEST(LargestFirstTest, OrdersBySizeWithTiesInInputOrder) {
  std::vector<InputText> texts(4);
  texts[0].text = std::string(10, 'a');
  texts[1].text = std::string(300, 'b');
  texts[2].text = std::string(10, 'c');
  texts[3].text = std::string(40, 'd');
  std::vector<FileJob> jobs(5);
  for (size_t i = 0; i < texts.size(); ++i) jobs[i].contents = &texts[i];
  jobs[4].path = "no/such/file.glsl";  // unknown size: last
  EXPECT_EQ(LargestFirst(jobs), (std::vector<size_t>{1, 3, 0, 2, 4}));
}

TEST(LargestFirstTest, ParallelForTakesTheGivenOrder) {
  const std::vector<size_t> order = {2, 0, 3, 1};
  std::vector<size_t> seen;
  ParallelFor(
      order.size(), 1, [&](size_t i) { seen.push_back(i); }, order);
  EXPECT_EQ(seen, order);  // one job: exactly that sequence
  std::vector<std::atomic<int>> calls(order.size());
  ParallelFor(
      order.size(), 2, [&](size_t i) { ++calls[i]; }, order);
  for (const auto& count : calls) EXPECT_EQ(count.load(), 1);
}

}  // namespace
}  // namespace shaderport::driver
