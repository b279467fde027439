#version 300 es
precision mediump float;
uniform vec4 fragColor;
out highp vec4 fragColor_1;
void main() {
  fragColor_1 = fragColor;
}
