precision mediump float;
void f(out void, in vec2);
void main() { gl_FragColor = vec4(1.0); }
