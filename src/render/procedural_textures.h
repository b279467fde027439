// Deterministic textures for channels the user gave no image for: a 2D pattern with
// gradients, a checkerboard and noise (so that filtering and mipmaps show), a cube
// map with a distinct tint per face, and a 3D value-noise volume.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace shaderport::render {

inline constexpr uint32_t kProcedural2DSize = 256;
inline constexpr uint32_t kProceduralCubeSize = 64;
inline constexpr uint32_t kProcedural3DSize = 32;

// RGBA8, rows in GL order (row 0 at v = 0).
std::vector<uint8_t> Procedural2D(uint32_t size);
// One face (0..5: +X -X +Y -Y +Z -Z), RGBA8.
std::vector<uint8_t> ProceduralCubeFace(uint32_t face, uint32_t size);
// size^3 texels, RGBA8.
std::vector<uint8_t> Procedural3D(uint32_t size);

}  // namespace shaderport::render
