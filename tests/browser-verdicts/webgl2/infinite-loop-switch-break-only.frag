#version 300 es
precision highp float;
out vec4 o;
// Browsers' infinite-loop check (webgl/infinite-loop): switch break only.
uniform bool run;
uniform float u;
void main(){ float y=0.0; while (true) { switch (int(u)) { case 0: break; default: y+=1.0; } } o = vec4(y); }
