#version 300 es
precision highp float;
out vec4 o;
// Browsers' infinite-loop check (webgl/infinite-loop): global true read.
uniform bool run;
uniform float u;
bool go = true; void main(){ float y= go ? 1.0 : 0.0; while (go) { y += 1.0; if (y > 3.0) break; } o = vec4(y); }
