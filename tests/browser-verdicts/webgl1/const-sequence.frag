// GLSL ES 1.00: browsers fold (1.0, 2.0) to 2.0.
precision mediump float;
const float c = (1.0, 2.0);
void main() { gl_FragColor = vec4(c); }
