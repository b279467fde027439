#version 300 es
precision highp float;
// Common code first: float is used before the pass's own default precision.
float half_of(float x) { return x * 0.5; }
precision highp float;
out vec4 color;
void main() {
  color = vec4(half_of(1.0));
}
