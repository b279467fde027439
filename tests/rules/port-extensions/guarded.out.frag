#version 300 es
#ifdef GL_OES_standard_derivatives
#endif
precision mediump float;
out highp vec4 fragColor;
void main() {
  fragColor = vec4(1.0);
}
