#version 300 es
// Bits of pow, exp and sin in a WebGL2 fragment shader that declares no int
// precision: its default is mediump, which must not reach the helpers' integer
// bit arithmetic (tests/render-parity/README.md).
precision highp float;
uniform float iTime;
out vec4 color;

vec4 Bits(float r, vec2 pixel) {
  uint u = floatBitsToUint(r);
  if (mod(floor(pixel.x), 2.0) > 0.5) return vec4(float(u & 255u), 0.0, 0.0, 1.0) / 255.0;
  return vec4(float(u >> 24u), float((u >> 16u) & 255u), float((u >> 8u) & 255u), 255.0) / 255.0;
}

void main() {
  vec2 pixel = gl_FragCoord.xy;
  float i = floor(pixel.x * 0.5) + 32.0 * floor(pixel.y);
  float v = (i * 0.0491357 - 100.0) * iTime;
  color = Bits(pow(abs(v), 0.4545) + exp(v * 0.05) + sin(v), pixel);
}
