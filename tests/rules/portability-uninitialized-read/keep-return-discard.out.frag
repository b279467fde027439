precision mediump float;
varying vec2 v;
float shade(float x) {
  float s;
  if (x < 0.0) return 0.0;
  else s = sqrt(x);
  return s;
}
void main() {
  float a;
  if (v.x > 0.5) {
    a = shade(v.y);
  } else {
    discard;
  }
  gl_FragColor = vec4(a);
}
