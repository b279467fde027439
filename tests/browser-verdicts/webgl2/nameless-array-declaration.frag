#version 300 es
precision mediump float;
// Declarations of an array type that name nothing: empty declarations to browsers.
uniform float [4];
vec3 [2];
const int N = 3;
float [N], named;
out vec4 c;
void main() {
  float [3];
  named[0] = 1.0;
  c = vec4(named[0]);
}
