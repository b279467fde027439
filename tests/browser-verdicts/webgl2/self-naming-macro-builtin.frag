#version 300 es
precision highp float;
// A macro that names a built-in in its body: browsers call the built-in there.
#define normalize(x) normalize(x + 1e-6)
out vec4 c;
void main() {
  vec2 d = normalize(gl_FragCoord.xy);
  c = vec4(d, normalize(vec3(1.0)).x, 1.0);
}
