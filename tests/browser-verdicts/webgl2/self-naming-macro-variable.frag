#version 300 es
precision highp float;
// A one-letter macro whose body assigns the variable of its own name.
#define T(V) (T = vec4(V, 0.0, 1.0), T * T)
out vec4 O;
void main() {
  vec4 T;
  O = T(gl_FragCoord.xy) + T(vec2(0.5));
}
