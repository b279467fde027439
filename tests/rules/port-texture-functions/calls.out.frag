#version 300 es
precision mediump float;
uniform sampler2D tex;
uniform samplerCube env;
in vec2 uv;
out highp vec4 fragColor;
void main() {
  vec4 a = texture(tex, uv);
  vec4 b = texture(env, vec3(uv, 1.0));
  vec4 c = textureProj(tex, vec3(uv, 1.0));
  fragColor = a + b + c + texture(tex, uv, 1.0);
}
