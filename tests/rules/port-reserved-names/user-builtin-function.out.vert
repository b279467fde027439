#version 300 es
in vec4 p;
mat3 transpose_(mat3 m);
mat3 transpose_(mat3 m) {
  return mat3(m[0][0], m[1][0], m[2][0], m[0][1], m[1][1], m[2][1], m[0][2], m[1][2], m[2][2]);
}
float round_(float x) { return floor(x + 0.5); }
void main() {
  gl_Position = vec4(transpose_(mat3(1.0)) * p.xyz, round_(p.w));
}
