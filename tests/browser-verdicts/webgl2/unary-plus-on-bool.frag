#version 300 es
precision mediump float;
out vec4 o;
void main() { bvec2 b = bvec2(true); bvec2 c = +b; bool d = +true; o = vec4(c.x && d); }
