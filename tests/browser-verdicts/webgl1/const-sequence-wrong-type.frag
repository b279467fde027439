precision mediump float;
// (0.0, 1.0, 0.0, 1.0) is the float 1.0, not a vec4.
const vec4 green = (0.0, 1.0, 0.0, 1.0);
void main() { gl_FragColor = green; }
