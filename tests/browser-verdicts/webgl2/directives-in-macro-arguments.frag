#version 300 es
precision highp float;
out vec4 o;
#define A 1
#define T(P, Q) vec4(P, Q, 0.0, 1.0)
void main() {
  o = T(
#if A == 1
    1.0,
#else
    undefinedName,
#endif
#ifdef B
    nothing
#else
    0.5
#endif
  );
}
