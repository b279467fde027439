#version 300 es
precision highp float;
uniform vec3 iResolution;
out vec4 outColor;
void mainImage(out vec4 c, in vec2 p) { c = vec4(p / iResolution.xy, 0.0, 1.0); }
void main() { mainImage(outColor, gl_FragCoord.xy); }
