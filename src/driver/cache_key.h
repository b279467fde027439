// The 128-bit keys of the result cache: a hash of everything a file's findings
// depend on. Every field is length-prefixed, so no two field lists hash alike by
// concatenation.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace shaderport::driver {

struct CacheKey {
  uint64_t high = 0;
  uint64_t low = 0;
  std::string Hex() const;  // 32 lowercase hex digits: the entry's file name
  friend bool operator==(const CacheKey&, const CacheKey&) = default;
};

// Two independent 64-bit lanes over 8-byte words: fast enough that hashing the
// text of 10,000 shaders costs a few milliseconds.
class KeyHasher {
 public:
  KeyHasher& Add(std::string_view bytes);
  KeyHasher& Add(uint64_t value);
  KeyHasher& Add(const CacheKey& key) { return Add(key.high).Add(key.low); }
  CacheKey Finish() const;

 private:
  void Word(uint64_t word);
  uint64_t a_ = 0x6a09e667f3bcc908ull;
  uint64_t b_ = 0xbb67ae8584caa73bull;
  uint64_t words_ = 0;
};

}  // namespace shaderport::driver
