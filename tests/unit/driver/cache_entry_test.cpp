#include "driver/cache_entry.h"

#include <gtest/gtest.h>

namespace shaderport::driver {
namespace {

const CacheKey kKey{0x0123456789abcdefull, 0xfedcba9876543210ull};

// A report as CheckFile leaves it: ranges into the file, its Common code, a
// generated header and nowhere, with notes and fixes.
struct Fixture {
  SourceManager sources;
  const SourceFile* common = &sources.Add("dir/common.glsl", "float c = 1;\n");
  FileReport report;

  Fixture() {
    const SourceFile& file = sources.Add("dir/pass.glsl", "void mainImage() { int x = 1.0; }\n");
    const SourceFile& header =
        sources.Add("<shadertoy header>", "uniform vec3 iResolution;\n", true);
    report.file = &file;
    report.dialect = "shadertoy";
    report.stage = "fragment";
    Diagnostic a = MakeDiagnostic(Severity::kError, "glslang/type", {file.Id(), 19, 30}, "bad");
    a.notes.push_back({{common->Id(), 0, 5}, "in Common"});
    a.notes.push_back({{}, "no location"});
    a.fixes.push_back({{file.Id(), 27, 30}, "1", FixSafety::kSuggestion});
    Diagnostic b = MakeDiagnostic(Severity::kWarning, "internal/generated-code",
                                  {header.Id(), 0, 7}, "header");
    Diagnostic c = MakeDiagnostic(Severity::kNote, "x/y", {}, "whole file");
    report.diagnostics = {a, b, c};
  }
};

TEST(CacheEntryTest, RoundTripsEveryKindOfRange) {
  Fixture fixture;
  const std::optional<std::string> bytes =
      EncodeCacheEntry(fixture.report, fixture.common, fixture.sources, kKey);
  ASSERT_TRUE(bytes);
  std::optional<CacheEntry> entry = DecodeCacheEntry(*bytes, kKey);
  ASSERT_TRUE(entry);
  ASSERT_TRUE(EntryFits(*entry, fixture.common));

  SourceManager& sources = fixture.sources;
  const FileReport restored =
      RestoreReport(std::move(*entry), "dir/pass.glsl", std::string(fixture.report.file->Text()),
                    fixture.common, sources);
  EXPECT_EQ(restored.dialect, "shadertoy");
  EXPECT_EQ(restored.stage, "fragment");
  EXPECT_EQ(restored.file->Text(), fixture.report.file->Text());
  ASSERT_EQ(restored.diagnostics.size(), 3u);
  const Diagnostic& a = restored.diagnostics[0];
  EXPECT_EQ(a.range, (SourceRange{restored.file->Id(), 19, 30}));
  EXPECT_EQ(a.severity, Severity::kError);
  EXPECT_EQ(a.rule_id, "glslang/type");
  EXPECT_EQ(a.message, "bad");
  EXPECT_EQ(a.notes[0].range, (SourceRange{fixture.common->Id(), 0, 5}));
  EXPECT_FALSE(a.notes[1].range.Valid());
  EXPECT_EQ(a.fixes[0].replacement, "1");
  EXPECT_EQ(a.fixes[0].safety, FixSafety::kSuggestion);
  // The generated header is rebuilt as a synthetic file after the checked one.
  const SourceFile& header = sources.Get(restored.diagnostics[1].range.file);
  EXPECT_TRUE(header.IsSynthetic());
  EXPECT_EQ(header.Name(), "<shadertoy header>");
  EXPECT_EQ(header.Text(), "uniform vec3 iResolution;\n");
  EXPECT_GT(header.Id(), restored.file->Id());
  EXPECT_FALSE(restored.diagnostics[2].range.Valid());
}

TEST(CacheEntryTest, EveryTruncationIsRejected) {
  Fixture fixture;
  const std::string bytes =
      *EncodeCacheEntry(fixture.report, fixture.common, fixture.sources, kKey);
  for (size_t size = 0; size < bytes.size(); ++size) {
    EXPECT_FALSE(DecodeCacheEntry(std::string_view(bytes).substr(0, size), kKey)) << size;
  }
  EXPECT_FALSE(DecodeCacheEntry(bytes + "x", kKey));
}

TEST(CacheEntryTest, EveryFlippedByteIsRejected) {
  Fixture fixture;
  const std::string bytes =
      *EncodeCacheEntry(fixture.report, fixture.common, fixture.sources, kKey);
  for (size_t at = 0; at < bytes.size(); ++at) {
    std::string broken = bytes;
    broken[at] = static_cast<char>(broken[at] ^ 0x20);
    EXPECT_FALSE(DecodeCacheEntry(broken, kKey)) << at;
  }
}

TEST(CacheEntryTest, AnEntryOfAnotherKeyOrNoEntryAtAllIsRejected) {
  Fixture fixture;
  const std::string bytes =
      *EncodeCacheEntry(fixture.report, fixture.common, fixture.sources, kKey);
  EXPECT_FALSE(DecodeCacheEntry(bytes, CacheKey{kKey.high, kKey.low + 1}));
  EXPECT_FALSE(DecodeCacheEntry("", kKey));
  EXPECT_FALSE(DecodeCacheEntry("{\"version\": 1, \"files\": []}\n", kKey));
  EXPECT_FALSE(DecodeCacheEntry(std::string(4096, '\0'), kKey));
}

TEST(CacheEntryTest, AnEntryThatNeedsCommonDoesNotFitAJobWithout) {
  Fixture fixture;
  const std::string bytes =
      *EncodeCacheEntry(fixture.report, fixture.common, fixture.sources, kKey);
  EXPECT_FALSE(EntryFits(*DecodeCacheEntry(bytes, kKey), nullptr));
}

TEST(CacheEntryTest, ARangeIntoAnotherOriginalFileIsNotCached) {
  Fixture fixture;
  const SourceFile& other = fixture.sources.Add("dir/other.glsl", "x");
  fixture.report.diagnostics[0].notes.push_back({{other.Id(), 0, 1}, "elsewhere"});
  EXPECT_FALSE(EncodeCacheEntry(fixture.report, fixture.common, fixture.sources, kKey));
}

TEST(CacheKeyTest, FieldsDoNotRunTogether) {
  EXPECT_NE(KeyHasher().Add("ab").Add("c").Finish(), KeyHasher().Add("a").Add("bc").Finish());
  EXPECT_NE(KeyHasher().Add("").Finish(), KeyHasher().Add(std::string(1, '\0')).Finish());
  EXPECT_EQ(KeyHasher().Add("same").Finish(), KeyHasher().Add("same").Finish());
  EXPECT_EQ(KeyHasher().Add("x").Finish().Hex().size(), 32u);
}

}  // namespace
}  // namespace shaderport::driver
