#version 300 es
precision highp float;
// An unnamed void first parameter: glslang accepts it, browsers do not.
out vec4 o;
void mainImage(out void, in vec2);
void main() { o = vec4(1.0); }
