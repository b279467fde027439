#version 300 es
precision mediump float;
uniform sampler2D tex;
#define SAMPLE(p) texture(tex, p)
in vec2 uv;
out highp vec4 fragColor;
void main() {
  fragColor = SAMPLE(uv) + SAMPLE(uv * 2.0);
}
