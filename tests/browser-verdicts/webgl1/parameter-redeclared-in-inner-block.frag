precision mediump float;
int f(int k) { { int k = 2; } return k; }
void main() { gl_FragColor = vec4(float(f(1))); }
