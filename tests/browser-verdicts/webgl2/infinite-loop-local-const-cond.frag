#version 300 es
precision highp float;
out vec4 o;
// Browsers' infinite-loop check (webgl/infinite-loop): local const cond.
uniform bool run;
uniform float u;
void main(){ bool go = true; float y=0.0; while (go) { y += 1.0; if (y > u) discard; } o = vec4(y); }
