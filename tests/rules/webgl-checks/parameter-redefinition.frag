precision mediump float;
int f(int k) { int k = k + 3; return k; }
void main() { gl_FragColor = vec4(float(f(1))); }
