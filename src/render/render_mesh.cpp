#include "render/render_mesh.h"

#include <cctype>
#include <cmath>
#include <string>

namespace shaderport::render {
namespace {

int ComponentCount(GLenum type) {
  switch (type) {
    case GL_FLOAT:
      return 1;
    case GL_FLOAT_VEC2:
      return 2;
    case GL_FLOAT_VEC3:
      return 3;
    case GL_FLOAT_VEC4:
      return 4;
    default:
      return 0;  // integer or matrix attributes keep their constant default
  }
}

}  // namespace

AttributeStream StreamForAttribute(std::string_view name) {
  std::string lower(name);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  // "vertex" contains "tex": drop it so that "vertexColor" is a colour, "Vertex" a position.
  for (size_t at = lower.find("vertex"); at != std::string::npos; at = lower.find("vertex")) {
    lower.erase(at, 6);
  }
  auto has = [&](std::string_view part) { return lower.find(part) != std::string::npos; };
  if (has("norm")) return AttributeStream::kNormal;
  if (has("tangent")) return AttributeStream::kTangent;
  if (has("uv") || has("tex") || has("coord")) return AttributeStream::kTexCoord;
  if (has("col")) return AttributeStream::kColor;
  return AttributeStream::kPosition;
}

const std::vector<float>& SphereMesh::Stream(AttributeStream stream) const {
  switch (stream) {
    case AttributeStream::kNormal:
      return normals;
    case AttributeStream::kTexCoord:
      return tex_coords;
    case AttributeStream::kColor:
      return colors;
    case AttributeStream::kTangent:
      return tangents;
    case AttributeStream::kPosition:
      break;
  }
  return positions;
}

SphereMesh MakeSphereMesh(int slices, int stacks) {
  SphereMesh mesh;
  const float pi = 3.14159265f;
  for (int j = 0; j <= stacks; ++j) {
    const float v = static_cast<float>(j) / static_cast<float>(stacks);
    const float theta = v * pi;
    for (int i = 0; i <= slices; ++i) {
      const float u = static_cast<float>(i) / static_cast<float>(slices);
      const float phi = u * 2.0f * pi;
      const float x = std::sin(theta) * std::cos(phi);
      const float y = std::cos(theta);
      const float z = std::sin(theta) * std::sin(phi);
      mesh.positions.insert(mesh.positions.end(), {x, y, z, 1.0f});
      mesh.normals.insert(mesh.normals.end(), {x, y, z, 0.0f});
      mesh.tex_coords.insert(mesh.tex_coords.end(), {u, 1.0f - v, 0.0f, 1.0f});
      mesh.colors.insert(mesh.colors.end(), {x * 0.5f + 0.5f, y * 0.5f + 0.5f, z * 0.5f + 0.5f, 1});
      mesh.tangents.insert(mesh.tangents.end(), {-std::sin(phi), 0.0f, std::cos(phi), 1.0f});
    }
  }
  const auto row = static_cast<uint32_t>(slices + 1);
  for (uint32_t j = 0; j < static_cast<uint32_t>(stacks); ++j) {
    for (uint32_t i = 0; i < static_cast<uint32_t>(slices); ++i) {
      const uint32_t a = j * row + i;
      const uint32_t b = a + row;
      mesh.indices.insert(mesh.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  }
  return mesh;
}

MeshBuffers UploadMeshForProgram(const GlFunctions& gl, GLuint program, const SphereMesh& mesh) {
  MeshBuffers result;
  GLint count = 0;
  gl.GetProgramiv(program, GL_ACTIVE_ATTRIBUTES, &count);
  for (GLint i = 0; i < count; ++i) {
    char name[256] = {};
    GLsizei length = 0;
    GLint size = 0;
    GLenum type = 0;
    gl.GetActiveAttrib(program, static_cast<GLuint>(i), sizeof(name), &length, &size, &type, name);
    const GLint location = gl.GetAttribLocation(program, name);
    const int components = ComponentCount(type);
    if (location < 0 || components == 0) continue;  // gl_VertexID and friends, int attributes
    const std::vector<float>& data = mesh.Stream(StreamForAttribute(name));
    GLuint buffer = 0;
    gl.GenBuffers(1, &buffer);
    result.buffers.push_back(buffer);
    gl.BindBuffer(GL_ARRAY_BUFFER, buffer);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)),
                  data.data(), GL_STATIC_DRAW);
    gl.VertexAttribPointer(static_cast<GLuint>(location), components, GL_FLOAT, GL_FALSE,
                           4 * sizeof(float), nullptr);
    gl.EnableVertexAttribArray(static_cast<GLuint>(location));
  }
  GLuint index_buffer = 0;
  gl.GenBuffers(1, &index_buffer);
  result.buffers.push_back(index_buffer);
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer);
  gl.BufferData(GL_ELEMENT_ARRAY_BUFFER,
                static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(uint32_t)),
                mesh.indices.data(), GL_STATIC_DRAW);
  result.index_count = static_cast<GLsizei>(mesh.indices.size());
  return result;
}

}  // namespace shaderport::render
