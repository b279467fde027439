#version 300 es
precision highp float;
uniform int u;
out vec4 o;
void main() {
  switch (u) { case 0: }
  o = vec4(1.0);
}
