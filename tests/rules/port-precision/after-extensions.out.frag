#version 300 es
precision highp float;
// the varying
in highp vec2 uv;
out highp vec4 fragColor;
void main() {
  fragColor = vec4(fwidth(uv), 0.0, 1.0);
  gl_FragDepth = 0.5;
}
