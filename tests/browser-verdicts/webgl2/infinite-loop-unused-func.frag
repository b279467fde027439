#version 300 es
precision highp float;
out vec4 o;
// Browsers' infinite-loop check (webgl/infinite-loop): unused func.
uniform bool run;
uniform float u;
void f(){ while (true) { } } void main(){ o = vec4(1.0); }
