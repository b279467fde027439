precision mediump float;
uniform sampler2D tex;
#define SAMPLE(p) texture2D(tex, p)
varying vec2 uv;
void main() {
  gl_FragColor = SAMPLE(uv) + SAMPLE(uv * 2.0);
}
