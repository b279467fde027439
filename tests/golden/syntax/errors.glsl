#version 300 es
varying vec2 uv;
float a = ;
void main() {
  float b = 1.0
  b = (b + ;
  if b) {}
  return;
}
float ok;
