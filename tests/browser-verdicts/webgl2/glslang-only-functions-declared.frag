#version 300 es
precision highp float;
// Names glslang has as built-ins and browsers do not: a shader may declare them.
out vec4 c;
const float memoryBarrier = 0.5;
float average(vec2 r) { return 0.5 * (r.x + r.y); }
int countLeadingZeros(int x) { return x; }
vec4 texture2DLodEXT(vec2 p) { return vec4(p, 0.0, 1.0); }
void main() { c = texture2DLodEXT(vec2(average(vec2(1.0)), float(countLeadingZeros(2)))) * memoryBarrier; }
