// The generated mesh a user vertex shader is drawn with: a unit sphere at the
// origin. Each active attribute is fed the stream its name suggests.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "render/gl_functions.h"

namespace shaderport::render {

enum class AttributeStream : uint8_t { kPosition, kNormal, kTexCoord, kColor, kTangent };

// "aNormal" -> kNormal, "TexCoord0" -> kTexCoord, "Vertex" -> kPosition...
AttributeStream StreamForAttribute(std::string_view name);

struct SphereMesh {
  // Four floats per vertex for each stream (w = 1 for positions and colours).
  std::vector<float> positions, normals, tex_coords, colors, tangents;
  std::vector<uint32_t> indices;
  const std::vector<float>& Stream(AttributeStream stream) const;
};

SphereMesh MakeSphereMesh(int slices, int stacks);

// Creates buffers for the program's active attributes on the bound VAO; returns the
// buffer names to delete and the index count to draw.
struct MeshBuffers {
  std::vector<GLuint> buffers;
  GLsizei index_count = 0;
};
MeshBuffers UploadMeshForProgram(const GlFunctions& gl, GLuint program, const SphereMesh& mesh);

}  // namespace shaderport::render
