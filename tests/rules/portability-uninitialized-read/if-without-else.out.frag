precision mediump float;
varying vec2 v;
void main() {
  vec3 base = vec3(0.0);
  if (v.x > 0.5) base = vec3(1.0, 0.5, 0.2);
  gl_FragColor = vec4(base, 1.0);
}
