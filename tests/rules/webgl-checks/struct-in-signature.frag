precision mediump float;
// A struct defined in a function's parameter list.
float area(struct Rect { float w; float h; } r) { return r.w * r.h; }
void main() { gl_FragColor = vec4(1.0); }
