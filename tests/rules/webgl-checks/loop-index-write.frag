precision mediump float;
void main() { float x = 0.0; for (int i = 0; i < 4; i++) { i = 2; x += 1.0; } gl_FragColor = vec4(x); }
