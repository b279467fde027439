#version 300 es
out highp vec4 fragColor;
precision highp float;
void main() {
  fragColor = vec4(1.0);
}
