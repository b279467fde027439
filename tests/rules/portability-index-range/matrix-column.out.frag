precision mediump float;
uniform mat3 m;
void main() {
  vec3 sum = vec3(0.0);
  for (int i = 0; i <= 3; i++) sum += m[i];
  gl_FragColor = vec4(sum, 1.0);
}
