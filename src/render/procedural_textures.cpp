#include "render/procedural_textures.h"

namespace shaderport::render {
namespace {

// A fixed integer hash, so textures are the same on every machine.
uint32_t Hash(uint32_t x, uint32_t y, uint32_t z) {
  uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ z * 0xcb1ab31fu;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return h;
}

uint8_t Byte(uint32_t value) { return static_cast<uint8_t>(value & 0xffu); }

}  // namespace

std::vector<uint8_t> Procedural2D(uint32_t size) {
  std::vector<uint8_t> texels(size_t{size} * size * 4);
  for (uint32_t y = 0; y < size; ++y) {
    for (uint32_t x = 0; x < size; ++x) {
      uint8_t* t = &texels[(size_t{y} * size + x) * 4];
      const bool check = ((x / 32) + (y / 32)) % 2 == 0;
      const uint32_t noise = Hash(x, y, 0);
      t[0] = Byte(x * 255 / (size - 1));
      t[1] = Byte(y * 255 / (size - 1));
      t[2] = check ? 200 : 56;
      t[3] = Byte(noise);
    }
  }
  return texels;
}

std::vector<uint8_t> ProceduralCubeFace(uint32_t face, uint32_t size) {
  static constexpr uint8_t kTint[6][3] = {{230, 80, 80},  {80, 200, 200}, {110, 200, 90},
                                          {180, 90, 190}, {90, 110, 230}, {220, 200, 80}};
  std::vector<uint8_t> texels(size_t{size} * size * 4);
  for (uint32_t y = 0; y < size; ++y) {
    for (uint32_t x = 0; x < size; ++x) {
      uint8_t* t = &texels[(size_t{y} * size + x) * 4];
      const uint32_t shade = 160 + (x + y) * 95 / (2 * (size - 1));
      for (int c = 0; c < 3; ++c) t[c] = Byte(kTint[face % 6][c] * shade / 255);
      t[3] = 255;
    }
  }
  return texels;
}

std::vector<uint8_t> Procedural3D(uint32_t size) {
  std::vector<uint8_t> texels(size_t{size} * size * size * 4);
  for (uint32_t z = 0; z < size; ++z) {
    for (uint32_t y = 0; y < size; ++y) {
      for (uint32_t x = 0; x < size; ++x) {
        const uint32_t h = Hash(x, y, z + 1);
        uint8_t* t = &texels[((size_t{z} * size + y) * size + x) * 4];
        t[0] = Byte(h);
        t[1] = Byte(h >> 8);
        t[2] = Byte(h >> 16);
        t[3] = Byte(h >> 24);
      }
    }
  }
  return texels;
}

}  // namespace shaderport::render
