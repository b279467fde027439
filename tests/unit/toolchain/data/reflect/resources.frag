#version 300 es
// Every kind of resource a WebGL2 fragment shader can declare.
precision highp float;
precision highp int;
precision highp isampler2D;
precision highp sampler2DShadow;
precision highp sampler2DArray;
struct Light {
  vec3 position;
  vec3 color;
};
uniform Light lights[2];
uniform mat3 normalMatrix;
uniform mat2x3 skew;
uniform ivec2 flags;
uniform uint unusedCounter;
layout(std140) uniform Material {
  vec4 albedo;
  float roughness;
} material;
layout(std140) uniform Globals {
  mat4 viewProjection;
  ivec4 frameInfo;
};
uniform isampler2D ids;
uniform sampler2DShadow shadowMap;
uniform sampler2DArray layers;
in vec3 v_normal;
in vec2 v_uv;
flat in int v_id;
layout(location = 0) out vec4 outColor;
layout(location = 1) out uvec2 outId;

void main() {
  vec3 n = normalize(normalMatrix * v_normal);
  float shadow = texture(shadowMap, vec3(v_uv, 0.5));
  ivec4 id = texelFetch(ids, ivec2(v_uv * 16.0), 0);
  vec4 layer = textureGradOffset(layers, vec3(v_uv, 1.0), vec2(0.0), vec2(0.0), ivec2(1, 0));
  vec3 light = lights[0].color * max(dot(n, lights[0].position), 0.0) * shadow;
  if (flags.x > 0) light += skew * vec2(1.0);
  outColor = vec4(light, 1.0) * material.albedo * layer + viewProjection[0] * float(frameInfo.x);
  outId = uvec2(id.xy) + uvec2(textureSize(ids, 0)) + uvec2(v_id);
  gl_FragDepth = material.roughness;
}
