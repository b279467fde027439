#version 300 es
uniform highp float u_time;
// The Book of Shaders, "Shaping functions": glslCanvas sets u_time, u_resolution
// and u_mouse; this excerpt declares only u_resolution.
#ifdef GL_ES
precision mediump float;
#endif

uniform vec2 u_resolution;

// Plot a line on Y using a value between 0.0-1.0
out highp vec4 fragColor;
float plot(vec2 st, float pct) {
  return smoothstep(pct - 0.02, pct, st.y) - smoothstep(pct, pct + 0.02, st.y);
}

void main() {
  vec2 st = gl_FragCoord.xy / u_resolution;
  float y = pow(st.x, 5.0 + 4.0 * sin(u_time));
  vec3 color = vec3(y);
  float pct = plot(st, y);
  color = (1.0 - pct) * color + pct * vec3(0.0, 1.0, 0.0);
  fragColor = vec4(color, 1.0);
}
