#version 300 es
precision mediump float;
in vec2 uv;
out highp vec4 fragColor;
void main() {
  fragColor = vec4(dFdx(uv), 0.0, 1.0);
}
