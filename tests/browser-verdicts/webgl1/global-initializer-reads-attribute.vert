precision mediump float;
attribute vec4 a;
float f = a.x;
void main() { gl_Position = vec4(f); }
