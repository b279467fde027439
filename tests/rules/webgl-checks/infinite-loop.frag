#version 300 es
precision mediump float;
uniform float u;
out vec4 color;
// No break or return leaves the loop; discard does not count.
void main() {
  for (;;) {
    if (u > 0.5) discard;
  }
  color = vec4(1.0);
}
