attribute vec4 p;
uniform float u;
void f(float q) { const float c = 2.0; const float d = c * 3.0; gl_Position = p * d * q * u; }
void main() { f(1.0); }
