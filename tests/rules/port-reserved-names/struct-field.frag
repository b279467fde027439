precision mediump float;
struct Light {
  vec3 color;
  float active;
};
uniform Light light;
void main() {
  Light copy = light;
  gl_FragColor = vec4(light.color * light.active * copy.active, 1.0);
}
