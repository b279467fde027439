#version 300 es
precision highp float;
void join(inout float a, float b) { a = min(a, b); }
out vec4 O;
void main() {
  float r = 1.0;
  #define join(a) join(r, a)
  join(0.5);
  #undef join
  join(r, 0.25);
  #ifndef join
  O = vec4(r);
  #endif
}
