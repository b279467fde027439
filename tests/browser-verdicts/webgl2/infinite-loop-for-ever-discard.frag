#version 300 es
precision highp float;
out vec4 o;
// Browsers' infinite-loop check (webgl/infinite-loop): for ever discard.
uniform bool run;
uniform float u;
void main(){ for (;;) { if (u > 0.5) discard; } o = vec4(1.0); }
