precision mediump float;
uniform float weights[4];
varying vec2 v;
void main() {
  float s = 0.0;
  for (int i = 4; i > -1; i--) s += weights[i] * v.x;
  gl_FragColor = vec4(s);
}
