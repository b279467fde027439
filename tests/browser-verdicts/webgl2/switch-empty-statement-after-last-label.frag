#version 300 es
precision highp float;
uniform int u;
out vec4 o;
void main() {
  switch (u) { case 0: ; }
  switch (u) { case 1: {} }
  switch (u) { default: int; }
  o = vec4(1.0);
}
