precision mediump float;
varying vec2 uv;
varying lowp vec4 tint;
void main() {
  gl_FragColor = vec4(uv, 0.0, 1.0) * tint;
}
