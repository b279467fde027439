precision mediump float;
// A variable may take a built-in function's name in GLSL ES 1.00.
void main() { float floor = 1.0; gl_FragColor = vec4(floor); }
