#include "driver/cache_key.h"

#include <cstring>

namespace shaderport::driver {
namespace {

// MurmurHash3's finaliser: every input bit affects every output bit.
uint64_t Mix(uint64_t x) {
  x ^= x >> 33;
  x *= 0xff51afd7ed558ccdull;
  x ^= x >> 33;
  x *= 0xc4ceb9fe1a85ec53ull;
  x ^= x >> 33;
  return x;
}

uint64_t RotateLeft(uint64_t x, int bits) { return (x << bits) | (x >> (64 - bits)); }

}  // namespace

std::string CacheKey::Hex() const {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string hex(32, '0');
  for (int i = 0; i < 16; ++i) {
    hex[static_cast<size_t>(15 - i)] = kDigits[(high >> (4 * i)) & 15];
    hex[static_cast<size_t>(31 - i)] = kDigits[(low >> (4 * i)) & 15];
  }
  return hex;
}

void KeyHasher::Word(uint64_t word) {
  ++words_;
  a_ = RotateLeft(a_ ^ Mix(word), 31) * 0x9e3779b97f4a7c15ull + 0x632be59bd9b4e019ull;
  b_ = RotateLeft(b_ + Mix(word ^ 0xd6e8feb86659fd93ull) + words_, 27) * 0xc2b2ae3d27d4eb4full;
}

KeyHasher& KeyHasher::Add(std::string_view bytes) {
  Word(bytes.size());
  size_t at = 0;
  for (; at + 8 <= bytes.size(); at += 8) {
    uint64_t word = 0;
    std::memcpy(&word, bytes.data() + at, 8);
    Word(word);
  }
  if (at < bytes.size()) {
    uint64_t word = 0;
    std::memcpy(&word, bytes.data() + at, bytes.size() - at);
    Word(word);
  }
  return *this;
}

KeyHasher& KeyHasher::Add(uint64_t value) {
  Word(value);
  return *this;
}

CacheKey KeyHasher::Finish() const {
  return {Mix(a_ ^ RotateLeft(b_, 17) ^ words_), Mix(b_ + Mix(a_))};
}

}  // namespace shaderport::driver
