precision mediump float;
// Reads the 32 taps, which do not fit the 31 varying vectors when packed.
uniform sampler2D uImage;
varying vec2 vTaps[32];
void main() {
  vec4 sum = vec4(0.0);
  for (int i = 0; i < 32; i++) sum += texture2D(uImage, vTaps[i]);
  gl_FragColor = sum / 32.0;
}
