precision mediump float;
varying vec2 uv;
float sample(float layout) {
  float smooth = layout * 2.0;
  return smooth;
}
void main() {
  float filter = sample(uv.x);
  gl_FragColor = vec4(filter);
}
