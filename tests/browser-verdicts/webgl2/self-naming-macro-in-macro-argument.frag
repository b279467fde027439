#version 300 es
precision highp float;
// A macro that calls the function of its own name with one more argument, used
// inside the arguments of another macro.
float z;
float line(vec2 p, vec2 a, float w) { return length(p - a) - w; }
#define line(p, a) line(p, a, z)
#define Min(a, b) min(a, b)
out vec4 c;
void main() {
  z = 0.1;
  float d = Min(line(gl_FragCoord.xy, vec2(1.0)), line(gl_FragCoord.xy, vec2(2.0)));
  c = vec4(d);
}
