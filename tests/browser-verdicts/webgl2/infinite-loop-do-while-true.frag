#version 300 es
precision highp float;
out vec4 o;
// Browsers' infinite-loop check (webgl/infinite-loop): do while true.
uniform bool run;
uniform float u;
void main(){ float y=0.0; do { y += 1.0; } while (true); o = vec4(y); }
