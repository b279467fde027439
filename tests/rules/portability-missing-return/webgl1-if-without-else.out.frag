precision mediump float;
varying vec2 v;
vec3 tint(float x) {
  if (x > 0.5) return vec3(1.0, 0.5, 0.2);
  return vec3(0.0);
}
void main() {
  gl_FragColor = vec4(tint(v.x), 1.0);
}
