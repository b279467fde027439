#version 300 es
precision highp float;
#define r(X) sin(0.5 * vec2(X + 1.0, X + 4.0))
#define M(h, w) max(r(w).x, h)
out vec4 c;
void main() {
  // M passes its empty argument on to r.
  c = vec4(M(0.5, ) + M(0.5, 2.0));
}
