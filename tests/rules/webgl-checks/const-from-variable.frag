precision mediump float;
void main() {
  float radius = 0.5;
  // A local const initialised from a variable: not a constant expression in GLSL ES 1.00.
  const float area = radius * radius;
  gl_FragColor = vec4(area);
}
