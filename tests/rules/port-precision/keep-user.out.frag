#version 300 es
#ifdef GL_ES
precision mediump float;
#endif
out highp vec4 fragColor;
void main() {
  fragColor = vec4(1.0);
}
