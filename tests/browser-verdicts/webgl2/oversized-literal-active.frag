#version 300 es
// The same literal where the code is compiled: an error in browsers too.
precision highp float;
out vec4 color;
void main() {
  color = vec4(1.0) / float(4294967296);
}
