#version 300 es
precision highp float;
out vec4 o;
// Browsers' infinite-loop check (webgl/infinite-loop): nested break only.
uniform bool run;
uniform float u;
void main(){ float y=0.0; while (true) { for (int i=0;i<2;i++) { if (u>0.5) break; } y+=1.0; } o = vec4(y); }
