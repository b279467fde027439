#version 300 es
precision mediump float;
out highp vec4 fragColor;
void main() {
  fragColor = vec4(1.0);
  gl_FragDepth = 0.5;
}
