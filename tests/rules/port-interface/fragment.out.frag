#version 300 es
precision mediump float;
in vec2 uv;
in lowp vec4 tint;
out highp vec4 fragColor;
void main() {
  fragColor = vec4(uv, 0.0, 1.0) * tint;
}
