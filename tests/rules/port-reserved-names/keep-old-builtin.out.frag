#version 300 es
precision mediump float;
uniform float level;
out highp vec4 fragColor;
void main() {
  float length = 2.0 * level;
  fragColor = vec4(length);
}
