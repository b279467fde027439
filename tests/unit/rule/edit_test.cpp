#include "source/edit.h"

#include <gtest/gtest.h>

#include <random>

namespace shaderport {
namespace {

TEST(ApplyEdits, ReplacesInsertsAndDeletesInAnyOrder) {
  const std::string original = "float x = 1;";
  const std::vector<Edit> edits = {{10, 11, "1.0"}, {0, 0, "const "}, {6, 7, ""}};
  const auto result = ApplyEdits(original, edits);
  ASSERT_TRUE(result);
  EXPECT_EQ(result->text, "const float  = 1.0;");
  EXPECT_EQ(result->map.OutputSize(), result->text.size());
  EXPECT_EQ(result->map.OriginalSize(), original.size());
}

TEST(ApplyEdits, RejectsOverlapsAndOutOfRange) {
  const std::string original = "abcdef";
  EXPECT_FALSE(ApplyEdits(original, std::vector<Edit>{{1, 3, "x"}, {2, 4, "y"}}));
  EXPECT_FALSE(ApplyEdits(original, std::vector<Edit>{{1, 4, "x"}, {2, 2, "y"}}));
  EXPECT_FALSE(ApplyEdits(original, std::vector<Edit>{{5, 9, "x"}}));
  EXPECT_FALSE(ApplyEdits(original, std::vector<Edit>{{3, 2, "x"}}));
  // Touching edits and two insertions at one point are fine, in the given order.
  const auto ok = ApplyEdits(original, std::vector<Edit>{{1, 3, "X"}, {3, 3, "1"}, {3, 3, "2"}});
  ASSERT_TRUE(ok);
  EXPECT_EQ(ok->text, "aX12def");
}

TEST(ApplyEdits, InsertionGoesBeforeAReplacementAtTheSameOffset) {
  // The version rule inserts at 0 while another rule replaces a word at 0.
  const std::string original = "attribute vec3 p;";
  for (const auto& edits : {std::vector<Edit>{{0, 9, "in"}, {0, 0, "#version 300 es\n"}},
                            std::vector<Edit>{{0, 0, "#version 300 es\n"}, {0, 9, "in"}}}) {
    const auto result = ApplyEdits(original, edits);
    ASSERT_TRUE(result);
    EXPECT_EQ(result->text, "#version 300 es\nin vec3 p;");
  }
}

TEST(SourceMap, MapsCopiedAndInsertedBytes) {
  const std::string original = "int a = 1;";
  const auto result = ApplyEdits(original, std::vector<Edit>{{0, 3, "float"}, {8, 9, "1.0"}});
  ASSERT_TRUE(result);
  ASSERT_EQ(result->text, "float a = 1.0;");
  const SourceMap& map = result->map;
  EXPECT_EQ(map.ToOriginal(0), 0u);  // inside "float" -> start of "int"
  EXPECT_EQ(map.ToOriginal(3), 0u);
  EXPECT_EQ(map.ToOriginal(6), 4u);    // 'a'
  EXPECT_EQ(map.ToOriginal(10), 8u);   // "1.0" -> "1"
  EXPECT_EQ(map.ToOriginal(13), 9u);   // ';'
  EXPECT_EQ(map.ToOriginal(14), 10u);  // end
  EXPECT_EQ(map.ToOriginalRange(0, 7), (std::pair<uint32_t, uint32_t>{0, 5}));
  EXPECT_EQ(map.ToOriginalRange(10, 13), (std::pair<uint32_t, uint32_t>{8, 9}));
  EXPECT_TRUE(map.IsCopied(6, 9));
  EXPECT_FALSE(map.IsCopied(4, 7));
}

TEST(SourceMap, ComposesRounds) {
  const std::string original = "aaa bbb ccc";
  const auto first = ApplyEdits(original, std::vector<Edit>{{4, 7, "B"}});  // "aaa B ccc"
  ASSERT_TRUE(first);
  const auto second = ApplyEdits(first->text, std::vector<Edit>{{0, 0, "// x\n"}, {6, 9, "C"}});
  ASSERT_TRUE(second);
  ASSERT_EQ(second->text, "// x\naaa B C");
  const SourceMap map = SourceMap::Compose(first->map, second->map);
  EXPECT_EQ(map.OutputSize(), second->text.size());
  EXPECT_EQ(map.ToOriginal(0), 0u);  // inserted header anchors at 0
  EXPECT_EQ(map.ToOriginal(6), 1u);  // second 'a'
  EXPECT_EQ(map.ToOriginal(9), 4u);  // 'B' stands for "bbb"
  EXPECT_EQ(map.ToOriginalRange(9, 10), (std::pair<uint32_t, uint32_t>{4, 7}));
  EXPECT_EQ(map.ToOriginalRange(11, 12), (std::pair<uint32_t, uint32_t>{8, 11}));
}

// Random edits: every copied output byte must map to an original byte with the same value.
TEST(SourceMap, RandomEditsMapCopiedBytesFaithfully) {
  std::mt19937 random(42);
  for (int trial = 0; trial < 200; ++trial) {
    std::string text;
    for (int i = 0; i < 40; ++i) text.push_back(static_cast<char>('a' + random() % 26));
    const std::string original = text;
    SourceMap map = SourceMap::Identity(static_cast<uint32_t>(text.size()));
    for (int round = 0; round < 3; ++round) {
      std::vector<Edit> edits;
      uint32_t at = 0;
      while (at < text.size()) {
        const uint32_t begin = at + random() % 6;
        const uint32_t end = std::min<uint32_t>(begin + random() % 3, text.size());
        if (begin > end) break;
        edits.push_back({begin, end, std::string(random() % 3, 'Z')});
        at = end + 1;
      }
      const auto edited = ApplyEdits(text, edits);
      ASSERT_TRUE(edited);
      map = SourceMap::Compose(map, edited->map);
      text = edited->text;
    }
    ASSERT_EQ(map.OutputSize(), text.size());
    for (uint32_t i = 0; i < text.size(); ++i) {
      if (map.IsCopied(i, i + 1)) {
        ASSERT_EQ(text[i], original[map.ToOriginal(i)]) << "trial " << trial << " offset " << i;
      } else {
        ASSERT_EQ(text[i], 'Z');
      }
    }
  }
}

}  // namespace
}  // namespace shaderport
