#include "render/uniform_values.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string_view>

#include "model/shipped_dialects.h"

namespace shaderport::render {
namespace {

struct UniformInfo {
  std::string name;  // without a trailing "[0]"
  GLint size = 1;
  GLenum type = 0;
  GLint location = -1;
};

std::string Lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool Contains(std::string_view haystack, std::string_view needle) {
  return haystack.find(needle) != std::string_view::npos;
}

bool IsSampler(GLenum type) {
  switch (type) {
    case GL_SAMPLER_2D:
    case GL_SAMPLER_3D:
    case GL_SAMPLER_CUBE:
    case GL_SAMPLER_2D_SHADOW:
    case GL_SAMPLER_CUBE_SHADOW:
    case GL_SAMPLER_2D_ARRAY:
    case GL_SAMPLER_2D_ARRAY_SHADOW:
    case GL_INT_SAMPLER_2D:
    case GL_INT_SAMPLER_3D:
    case GL_INT_SAMPLER_CUBE:
    case GL_INT_SAMPLER_2D_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_2D:
    case GL_UNSIGNED_INT_SAMPLER_3D:
    case GL_UNSIGNED_INT_SAMPLER_CUBE:
    case GL_UNSIGNED_INT_SAMPLER_2D_ARRAY:
      return true;
    default:
      return false;
  }
}

std::vector<float> Identity(int n) {
  std::vector<float> m(static_cast<size_t>(n * n), 0.0f);
  for (int i = 0; i < n; ++i) m[static_cast<size_t>(i * n + i)] = 1.0f;
  return m;
}

// Fills `count` elements of `components` floats each with the generic default.
void SetGenericFloats(const GlFunctions& gl, const UniformInfo& u, int components,
                      const RenderRequest& request, float time) {
  const std::string name = Lower(u.name);
  std::array<float, 4> value = {0.5f, 0.5f, 0.5f, 1.0f};
  const float w = static_cast<float>(request.width);
  const float h = static_cast<float>(request.height);
  if (Contains(name, "texel")) {
    value = {1.0f / w, 1.0f / h, 0.0f, 0.0f};
  } else if (Contains(name, "resolution") || Contains(name, "viewport") || Contains(name, "size")) {
    value = {w, h, 1.0f, 1.0f};
  } else if (Contains(name, "time")) {
    value = {time, time, time, time};
  }
  std::vector<float> data;
  for (GLint i = 0; i < u.size; ++i)
    data.insert(data.end(), value.begin(), value.begin() + components);
  switch (components) {
    case 1:
      gl.Uniform1fv(u.location, u.size, data.data());
      break;
    case 2:
      gl.Uniform2fv(u.location, u.size, data.data());
      break;
    case 3:
      gl.Uniform3fv(u.location, u.size, data.data());
      break;
    default:
      gl.Uniform4fv(u.location, u.size, data.data());
      break;
  }
}

void SetMatrix(const GlFunctions& gl, const UniformInfo& u, int n, float aspect) {
  const std::string name = Lower(u.name);
  std::vector<float> m = Identity(n);
  if (n == 4 && Contains(name, "proj")) {
    m = PerspectiveMatrix(aspect);
  } else if (n == 4 && Contains(name, "view")) {
    m = ViewMatrix();
  }
  std::vector<float> data;
  for (GLint i = 0; i < u.size; ++i) data.insert(data.end(), m.begin(), m.end());
  if (n == 2) gl.UniformMatrix2fv(u.location, u.size, GL_FALSE, data.data());
  if (n == 3) gl.UniformMatrix3fv(u.location, u.size, GL_FALSE, data.data());
  if (n == 4) gl.UniformMatrix4fv(u.location, u.size, GL_FALSE, data.data());
}

void SetInts(const GlFunctions& gl, const UniformInfo& u, int components, int value) {
  std::vector<GLint> data(static_cast<size_t>(u.size * components), value);
  if (components == 1) gl.Uniform1iv(u.location, u.size, data.data());
  if (components == 2) gl.Uniform2iv(u.location, u.size, data.data());
  if (components == 3) gl.Uniform3iv(u.location, u.size, data.data());
  if (components == 4) gl.Uniform4iv(u.location, u.size, data.data());
}

void SetUints(const GlFunctions& gl, const UniformInfo& u, int components) {
  std::vector<GLuint> data(static_cast<size_t>(u.size * components), 1u);
  if (components == 1) gl.Uniform1uiv(u.location, u.size, data.data());
  if (components == 2) gl.Uniform2uiv(u.location, u.size, data.data());
  if (components == 3) gl.Uniform3uiv(u.location, u.size, data.data());
  if (components == 4) gl.Uniform4uiv(u.location, u.size, data.data());
}

// What a ShaderToy uniform is fed for one frame.
struct SiteValues {
  const RenderRequest& request;
  float time = 0.0f;
  float delta = 0.0f;
  int frame = 0;
  const std::array<std::array<float, 3>, 4>& channel_res;
};

using Feed = void (*)(const GlFunctions& gl, const UniformInfo& u, const SiteValues& v);

// One entry per uniform of rules/dialects/shadertoy.toml (the site's and its entry
// points'), by the model's name; a test holds the two to the same names.
struct Feeder {
  std::string_view name;
  Feed feed;
};

constexpr Feeder kFeeders[] = {
    {"iResolution",
     [](const GlFunctions& gl, const UniformInfo& u, const SiteValues& v) {
       const float r[3] = {static_cast<float>(v.request.width),
                           static_cast<float>(v.request.height), 1.0f};
       gl.Uniform3fv(u.location, 1, r);
     }},
    {"iTime", [](const GlFunctions& gl, const UniformInfo& u,
                 const SiteValues& v) { gl.Uniform1fv(u.location, 1, &v.time); }},
    {"iTimeOffset", [](const GlFunctions& gl, const UniformInfo& u,
                       const SiteValues& v) { gl.Uniform1fv(u.location, 1, &v.time); }},
    {"iTimeDelta", [](const GlFunctions& gl, const UniformInfo& u,
                      const SiteValues& v) { gl.Uniform1fv(u.location, 1, &v.delta); }},
    {"iFrameRate",
     [](const GlFunctions& gl, const UniformInfo& u, const SiteValues& v) {
       gl.Uniform1fv(u.location, 1, &v.request.inputs.frame_rate);
     }},
    {"iFrame", [](const GlFunctions& gl, const UniformInfo& u,
                  const SiteValues& v) { gl.Uniform1iv(u.location, 1, &v.frame); }},
    {"iMouse",
     [](const GlFunctions& gl, const UniformInfo& u, const SiteValues& v) {
       gl.Uniform4fv(u.location, 1, v.request.inputs.mouse.data());
     }},
    {"iDate",
     [](const GlFunctions& gl, const UniformInfo& u, const SiteValues& v) {
       gl.Uniform4fv(u.location, 1, v.request.inputs.date.data());
     }},
    {"iSampleRate",
     [](const GlFunctions& gl, const UniformInfo& u, const SiteValues&) {
       const float rate = 44100.0f;
       gl.Uniform1fv(u.location, 1, &rate);
     }},
    {"iSampleOffset",
     [](const GlFunctions& gl, const UniformInfo& u, const SiteValues&) {
       const GLint zero = 0;
       gl.Uniform1iv(u.location, 1, &zero);
     }},
    {"iChannelTime",
     [](const GlFunctions& gl, const UniformInfo& u, const SiteValues& v) {
       const float times[4] = {v.time, v.time, v.time, v.time};
       gl.Uniform1fv(u.location, std::min(u.size, 4), times);
     }},
    {"iChannelResolution",
     [](const GlFunctions& gl, const UniformInfo& u, const SiteValues& v) {
       float res[12];
       for (size_t i = 0; i < 4; ++i) std::copy_n(v.channel_res[i].data(), 3, &res[i * 3]);
       gl.Uniform3fv(u.location, std::min(u.size, 4), res);
     }},
    {"unViewport",
     [](const GlFunctions& gl, const UniformInfo& u, const SiteValues& v) {
       const float r[4] = {0.0f, 0.0f, static_cast<float>(v.request.width),
                           static_cast<float>(v.request.height)};
       gl.Uniform4fv(u.location, 1, r);
     }},
    {"unCorners",
     [](const GlFunctions& gl, const UniformInfo& u, const SiteValues&) {
       // The +Z face seen from the origin: bottom-left, bottom-right, top-right,
       // top-left, then the ray origin (the order the site's main() mixes them in).
       const float corners[15] = {-1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1, 0, 0, 0};
       gl.Uniform3fv(u.location, std::min(u.size, 5), corners);
     }},
};

const Feeder* FindFeeder(std::string_view name) {
  for (const Feeder& feeder : kFeeders) {
    if (feeder.name == name) return &feeder;
  }
  return nullptr;
}

// ShaderToy's uniforms by the model's names (an old name such as iGlobalTime is fed
// as the name the site renamed it to); false when `u` is not one of them.
bool SetShaderToyUniform(const GlFunctions& gl, const UniformInfo& u, const SiteValues& values) {
  const model::HarnessDialect& site = model::ShaderToyDialect();
  std::string_view name = u.name;
  for (const auto& [old_name, new_name] : site.renames) {
    if (old_name == name) name = new_name;
  }
  if (site.FindProvided(name) == nullptr) return false;
  const Feeder* feeder = FindFeeder(name);
  if (feeder == nullptr) return false;  // a channel declared as a non-sampler: generic values
  feeder->feed(gl, u, values);
  return true;
}

}  // namespace

std::vector<std::string_view> FedShaderToyUniforms() {
  std::vector<std::string_view> names;
  for (const Feeder& feeder : kFeeders) names.push_back(feeder.name);
  return names;
}

std::vector<float> PerspectiveMatrix(float aspect) {
  const float fov = 60.0f * 3.14159265f / 180.0f;
  const float f = 1.0f / std::tan(fov / 2.0f);
  const float near_plane = 0.1f;
  const float far_plane = 100.0f;
  std::vector<float> m(16, 0.0f);
  m[0] = f / aspect;
  m[5] = f;
  m[10] = (far_plane + near_plane) / (near_plane - far_plane);
  m[11] = -1.0f;
  m[14] = 2.0f * far_plane * near_plane / (near_plane - far_plane);
  return m;
}

std::vector<float> ViewMatrix() {
  std::vector<float> m = Identity(4);
  m[14] = -3.0f;  // camera 3 units back along +Z, looking at the origin
  return m;
}

void SetUniforms(const GlFunctions& gl, GLuint program, const RenderRequest& request,
                 int frame_index, ProgramTextures& textures, const PassChannels& channels,
                 const ChannelOverrides& overrides) {
  GLint count = 0;
  gl.GetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
  std::vector<UniformInfo> uniforms;
  for (GLint i = 0; i < count; ++i) {
    char buffer[256] = {};
    GLsizei length = 0;
    UniformInfo u;
    gl.GetActiveUniform(program, static_cast<GLuint>(i), sizeof(buffer), &length, &u.size, &u.type,
                        buffer);
    u.name.assign(buffer, static_cast<size_t>(length));
    u.location = gl.GetUniformLocation(program, u.name.c_str());
    if (u.location < 0) continue;  // a uniform block member
    if (u.name.size() > 3 && u.name.ends_with("[0]")) u.name.resize(u.name.size() - 3);
    uniforms.push_back(std::move(u));
  }
  // Samplers first, so iChannelResolution knows the texture sizes.
  std::array<std::array<float, 3>, 4> channel_res{};
  size_t unit = 0;
  for (const UniformInfo& u : uniforms) {
    if (!IsSampler(u.type)) continue;
    if (unit >= kMaxTextureUnits) break;
    const auto this_unit = static_cast<GLint>(unit);
    gl.Uniform1iv(u.location, 1, &this_unit);
    gl.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    if (!textures.created)
      textures.units.push_back(CreateTextureUnit(gl, u.name, u.type, request, channels, overrides));
    const ProgramTextures::Unit& entry = textures.units[unit++];
    std::array<float, 3> size = entry.size;
    if (entry.follows_buffer && overrides[static_cast<size_t>(entry.channel)].texture != 0) {
      const ChannelOverride& o = overrides[static_cast<size_t>(entry.channel)];
      gl.BindTexture(GL_TEXTURE_2D, o.texture);
      size = {o.width, o.height, 1.0f};
    } else {
      gl.BindTexture(entry.target, entry.name);
    }
    gl.BindSampler(static_cast<GLuint>(this_unit), entry.sampler);
    if (entry.channel >= 0) channel_res[static_cast<size_t>(entry.channel)] = size;
  }
  textures.created = true;
  gl.ActiveTexture(GL_TEXTURE0);
  const float aspect = static_cast<float>(request.width) / static_cast<float>(request.height);
  const float delta = request.inputs.frame_rate > 0 ? 1.0f / request.inputs.frame_rate : 0.0f;
  const float time = request.inputs.time + delta * static_cast<float>(frame_index);
  const SiteValues site_values{request, time, delta, request.inputs.frame + frame_index,
                               channel_res};
  for (const UniformInfo& u : uniforms) {
    if (IsSampler(u.type)) continue;
    // Uniforms the render's own transforms declare (an opaque zero) keep GL's 0.
    if (u.name.starts_with("shaderport_")) continue;
    if (SetShaderToyUniform(gl, u, site_values)) continue;
    switch (u.type) {
      case GL_FLOAT:
        SetGenericFloats(gl, u, 1, request, time);
        break;
      case GL_FLOAT_VEC2:
        SetGenericFloats(gl, u, 2, request, time);
        break;
      case GL_FLOAT_VEC3:
        SetGenericFloats(gl, u, 3, request, time);
        break;
      case GL_FLOAT_VEC4:
        SetGenericFloats(gl, u, 4, request, time);
        break;
      case GL_INT:
      case GL_BOOL:
        SetInts(gl, u, 1, 1);
        break;
      case GL_INT_VEC2:
      case GL_BOOL_VEC2:
        SetInts(gl, u, 2, 1);
        break;
      case GL_INT_VEC3:
      case GL_BOOL_VEC3:
        SetInts(gl, u, 3, 1);
        break;
      case GL_INT_VEC4:
      case GL_BOOL_VEC4:
        SetInts(gl, u, 4, 1);
        break;
      case GL_UNSIGNED_INT:
        SetUints(gl, u, 1);
        break;
      case GL_UNSIGNED_INT_VEC2:
        SetUints(gl, u, 2);
        break;
      case GL_UNSIGNED_INT_VEC3:
        SetUints(gl, u, 3);
        break;
      case GL_UNSIGNED_INT_VEC4:
        SetUints(gl, u, 4);
        break;
      case GL_FLOAT_MAT2:
        SetMatrix(gl, u, 2, aspect);
        break;
      case GL_FLOAT_MAT3:
        SetMatrix(gl, u, 3, aspect);
        break;
      case GL_FLOAT_MAT4:
        SetMatrix(gl, u, 4, aspect);
        break;
      default:
        break;  // non-square matrices keep their zero default
    }
  }
}

}  // namespace shaderport::render
