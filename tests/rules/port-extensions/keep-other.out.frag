#version 300 es
#extension GL_EXT_made_up : enable
precision mediump float;
out highp vec4 fragColor;
void main() {
  fragColor = vec4(1.0);
}
