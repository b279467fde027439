#version 300 es
precision mediump float;
uniform sampler2D texture_;
in vec2 uv;
out highp vec4 fragColor;
void main() {
  fragColor = texture(texture_, uv);
}
