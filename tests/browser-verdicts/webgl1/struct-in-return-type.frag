precision mediump float;
// A struct defined in a return type compiles in browsers.
struct S { float x; } f() { return S(1.0); }
void main() { gl_FragColor = vec4(f().x); }
