#version 300 es
invariant out highp vec4 v;
in vec4 p;
void main() {
  v = p;
  gl_Position = p;
}
