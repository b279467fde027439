precision mediump float;
varying vec2 v;
void main() {
  vec3 col;
  if (v.x > 0.5) {
    col = vec3(1.0);
  } else if (v.y > 0.5) {
    col = vec3(0.5);
  } else {
    col = vec3(0.0);
  }
  float k = v.x > 0.2 ? (col.r > 0.1 ? 1.0 : 0.0) : 2.0;
  gl_FragColor = vec4(col * k, 1.0);
}
