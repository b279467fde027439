// GLSL ES 1.00 allows a new overload of a built-in.
precision mediump float;
float sin(vec2 x, vec2 y) { return x.x; }
void main() { gl_FragColor = vec4(sin(vec2(1.0), vec2(2.0))); }
