#version 300 es
precision mediump float;

// Paints everything white.
out highp vec4 fragColor;
void main() {
  fragColor = vec4(1.0);
  fragColor.a = 0.5;
}
