#version 300 es
precision highp float;
out vec4 o;
// Browsers' infinite-loop check (webgl/infinite-loop): local nonconst init.
uniform bool run;
uniform float u;
void main(){ bool go = u > 0.5; float y=0.0; while (go) { y += 1.0; } o = vec4(y); }
