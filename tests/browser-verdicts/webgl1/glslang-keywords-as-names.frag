precision mediump float;
// Words glslang reserves that browsers allow as names in GLSL ES 1.00.
void main() { float filter = 1.0; float common = 2.0; float case = filter + common; gl_FragColor = vec4(case); }
