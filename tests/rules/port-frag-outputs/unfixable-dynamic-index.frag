precision mediump float;
uniform int i;
void main() {
  gl_FragData[i] = vec4(1.0);
}
