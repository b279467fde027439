attribute vec4 p;
// Two globals on one line: the second reads a uniform, which browsers allow in ES 1.00.
uniform float u; float g = u;
void main() { gl_Position = p * g; }
