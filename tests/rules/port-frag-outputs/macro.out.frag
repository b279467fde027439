#version 300 es
precision mediump float;
#define OUT fragColor
out highp vec4 fragColor;
void main() {
  OUT = vec4(1.0);
}
