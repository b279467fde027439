#include "validate/snprintf_fast_path.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>

namespace shaderport::validate {
namespace {

// Called through a volatile pointer so that the compiler cannot fold or check the
// format at build time: the call as glslang makes it, resolved by the same link.
int (*volatile format_into)(char*, size_t, const char*, ...) = &std::snprintf;

TEST(SnprintfFastPathTest, CopiesAStringWithLibcsResultAndTruncation) {
  if (!SnprintfFastPathLinked()) GTEST_SKIP() << "this build links libc's snprintf unwrapped";
  const uint64_t before = SnprintfFastPathCopiesOnThisThread();
  std::array<char, 8> out{};
  out.fill('x');
  EXPECT_EQ(format_into(out.data(), out.size(), "%s", "+="), 2);
  EXPECT_STREQ(out.data(), "+=");
  // Too long: size - 1 bytes and a NUL, and the whole length returned.
  EXPECT_EQ(format_into(out.data(), 4, "%s", "uniform"), 7);
  EXPECT_STREQ(out.data(), "uni");
  EXPECT_EQ(out[4], 'x');  // nothing written past `size`
  // Size 0 writes nothing (a null buffer is allowed) and still counts the length.
  EXPECT_EQ(format_into(nullptr, 0, "%s", "abc"), 3);
  EXPECT_EQ(SnprintfFastPathCopiesOnThisThread(), before + 3);
}

TEST(SnprintfFastPathTest, EveryOtherCallGoesToLibc) {
  if (!SnprintfFastPathLinked()) GTEST_SKIP() << "this build links libc's snprintf unwrapped";
  const uint64_t before = SnprintfFastPathCopiesOnThisThread();
  std::array<char, 16> out{};
  EXPECT_EQ(format_into(out.data(), out.size(), "%d", 42), 2);
  EXPECT_STREQ(out.data(), "42");
  EXPECT_EQ(format_into(out.data(), out.size(), "%s!", "a"), 2);
  EXPECT_STREQ(out.data(), "a!");
  EXPECT_EQ(format_into(out.data(), out.size(), "%5s", "a"), 5);
  EXPECT_STREQ(out.data(), "    a");
  const char* null_text = nullptr;
  const int printed = format_into(out.data(), out.size(), "%s", null_text);
  EXPECT_EQ(std::string(out.data()), "(null)");  // glibc's spelling of a null string
  EXPECT_EQ(printed, 6);
  EXPECT_EQ(SnprintfFastPathCopiesOnThisThread(), before);
}

}  // namespace
}  // namespace shaderport::validate
