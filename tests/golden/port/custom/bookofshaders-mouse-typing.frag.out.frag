#version 300 es
uniform highp float u_time;
uniform highp vec2 u_mouse;
// A Book of Shaders exercise as students write it: int literals where floats
// belong (desktop drivers accept them, ES does not). u_mouse and u_time come
// from glslCanvas.
#ifdef GL_ES
precision mediump float;
#endif

uniform vec2 u_resolution;

out highp vec4 fragColor;
void main() {
  vec2 st = gl_FragCoord.xy / u_resolution.xy;
  vec2 m = u_mouse / u_resolution;
  float d = distance(st, m) * 2.0;
  float ring = step(0.5, fract(d * 8.0 - u_time));
  vec3 color = mix(vec3(0.1, 0.2, 0.4), vec3(1, 0.8, 0.3), ring);
  fragColor = vec4(color, 1);
}
