#version 300 es
precision mediump float;
uniform sampler2D tex;
// A user function that happens to share the old name: not a built-in call.
out highp vec4 fragColor;
vec4 texture2D(sampler2D s, vec2 p, int n) {
  return vec4(float(n));
}
void main() {
  fragColor = texture2D(tex, vec2(0.5), 3);
}
