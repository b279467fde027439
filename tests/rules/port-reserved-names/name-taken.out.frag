#version 300 es
precision mediump float;
uniform float sample_;
uniform float sample_1;
out highp vec4 fragColor;
void main() {
  fragColor = vec4(sample_1 + sample_);
}
