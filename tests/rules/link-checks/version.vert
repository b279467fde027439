#version 300 es
// Ported to GLSL ES 3.00 while the fragment shader is still GLSL ES 1.00.
in vec4 position;
out vec2 vUv;
void main() { vUv = position.xy; gl_Position = position; }
