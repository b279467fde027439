#version 300 es
precision mediump float;
in vec2 uv;
out highp vec4 fragColor;
float sample_(float layout_) {
  float smooth_ = layout_ * 2.0;
  return smooth_;
}
void main() {
  float filter_ = sample_(uv.x);
  fragColor = vec4(filter_);
}
