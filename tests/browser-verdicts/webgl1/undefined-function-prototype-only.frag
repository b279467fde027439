precision mediump float;
// A prototype nobody calls is fine.
float u(float x);
void main() { gl_FragColor = vec4(1.0); }
