#include "source/source_file.h"

#include <gtest/gtest.h>

#include "source/source_manager.h"

namespace shaderport {
namespace {

TEST(SourceFileTest, LocationsCountBytesFromOne) {
  const SourceFile file(0, "a.frag", "ab\ncd\r\nef\rg");
  EXPECT_EQ(file.LineCount(), 4u);
  EXPECT_EQ(file.LocationOf(0), (LineColumn{1, 1}));
  EXPECT_EQ(file.LocationOf(3), (LineColumn{2, 1}));
  EXPECT_EQ(file.LocationOf(4), (LineColumn{2, 2}));
  EXPECT_EQ(file.LocationOf(7), (LineColumn{3, 1}));
  EXPECT_EQ(file.LocationOf(10), (LineColumn{4, 1}));
}

TEST(SourceFileTest, LineTextDropsTerminators) {
  const SourceFile file(0, "a.frag", "ab\ncd\r\nef\rg");
  EXPECT_EQ(file.LineText(1), "ab");
  EXPECT_EQ(file.LineText(2), "cd");
  EXPECT_EQ(file.LineText(3), "ef");
  EXPECT_EQ(file.LineText(4), "g");
  EXPECT_EQ(file.LineText(5), "");
}

TEST(SourceFileTest, OffsetsPastTheEndAreClamped) {
  const SourceFile file(0, "a.frag", "abc\n");
  EXPECT_EQ(file.LocationOf(100), (LineColumn{2, 1}));
  EXPECT_EQ(file.OffsetOf({1, 99}), 3u);
  EXPECT_EQ(file.OffsetOf({1, 2}), 1u);
}

TEST(SourceFileTest, EmptyFileHasOneLine) {
  const SourceFile file(0, "e.frag", "");
  EXPECT_EQ(file.LineCount(), 1u);
  EXPECT_EQ(file.LocationOf(0), (LineColumn{1, 1}));
}

TEST(SourceManagerTest, ReferencesStayValidAsFilesAreAdded) {
  SourceManager sources;
  const SourceFile& first = sources.Add("one", "1");
  for (int i = 0; i < 1000; ++i) sources.Add("more", "x");
  EXPECT_EQ(first.Text(), "1");
  EXPECT_EQ(&sources.Get(0), &first);
  EXPECT_EQ(sources.Get(1000).Id(), 1000u);
}

}  // namespace
}  // namespace shaderport
