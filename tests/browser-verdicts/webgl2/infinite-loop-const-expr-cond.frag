#version 300 es
precision highp float;
out vec4 o;
// Browsers' infinite-loop check (webgl/infinite-loop): const expr cond.
uniform bool run;
uniform float u;
const int N = 3; void main(){ float y=0.0; while (N > 2) { y += 1.0; } o = vec4(y); }
