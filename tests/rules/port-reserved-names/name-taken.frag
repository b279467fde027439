precision mediump float;
uniform float sample_;
uniform float sample;
void main() {
  gl_FragColor = vec4(sample + sample_);
}
