#version 300 es
precision highp float;
out vec4 c;
// average is GL_INTEL_shader_integer_functions2 in glslang; browsers have no such built-in.
void main() { c = vec4(float(average(1, 3))); }
