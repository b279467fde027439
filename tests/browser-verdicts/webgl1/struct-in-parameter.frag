precision mediump float;
void f(struct S { float x; } s) {}
void main() { gl_FragColor = vec4(1.0); }
