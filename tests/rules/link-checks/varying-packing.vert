// 32 blur taps as a vec2[32] varying: an array takes 32 consecutive rows, past Chromium's 31.
attribute vec4 position;
uniform vec2 uTexel;
varying vec2 vTaps[32];
void main() {
  for (int i = 0; i < 32; i++) vTaps[i] = position.xy + float(i - 16) * uTexel;
  gl_Position = position;
}
