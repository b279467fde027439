#version 300 es
// Probe (h), WebGL2 form drawn as it is (no ShaderToy composition; the alpha channel is
// the shader's own): NaN, +inf, -inf written straight to the RGBA8 output, alpha included.
// Columns (8 px wide), whole height: 0: vec4(NaN)  1: vec4(+inf)  2: vec4(-inf)
// 3: vec4(NaN, 0.5, inf, -inf)
precision highp float;
uniform vec3 iResolution;
uniform float iTime;
out vec4 color;
void main() {
  int column = int(gl_FragCoord.x) / 8;
  float zero = iTime - 1.0;
  float nan = zero / zero;
  float inf = 1.0 / zero;
  vec4 v = vec4(0.0, 0.0, 1.0, 1.0);
  if (column == 0) v = vec4(nan);
  else if (column == 1) v = vec4(inf);
  else if (column == 2) v = vec4(-inf);
  else if (column == 3) v = vec4(nan, 0.5, inf, -inf);
  color = v;
}
