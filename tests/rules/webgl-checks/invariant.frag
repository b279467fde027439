precision mediump float;
// gl_FrontFacing cannot be invariant.
invariant gl_FrontFacing;
void main() { gl_FragColor = vec4(gl_FrontFacing ? 1.0 : 0.0); }
