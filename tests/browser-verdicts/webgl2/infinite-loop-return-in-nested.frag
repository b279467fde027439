#version 300 es
precision highp float;
out vec4 o;
// Browsers' infinite-loop check (webgl/infinite-loop): return in nested.
uniform bool run;
uniform float u;
void main(){ o = vec4(0.0); while (true) { for (int i=0;i<2;i++) { if (u>0.5) return; } } }
