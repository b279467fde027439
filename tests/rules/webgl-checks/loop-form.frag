precision mediump float;
void main() { float x = 0.0; for (int i = 0; i < 4; i += 1) { x += 1.0; } while (x > 0.0) { x -= 1.0; } gl_FragColor = vec4(x); }
