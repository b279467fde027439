#version 300 es
precision mediump float;
struct Light {
  vec3 color;
  float active_;
};
uniform Light light;
out highp vec4 fragColor;
void main() {
  Light copy = light;
  fragColor = vec4(light.color * light.active_ * copy.active_, 1.0);
}
