#version 300 es
precision highp float;
uniform sampler2D tex;
uniform vec3 light;
struct Hit { float t; vec3 n; };
out vec4 color;

Hit trace(vec3 ro, vec3 rd) {
  return Hit(length(ro) - 1.0, normalize(ro + rd));
}

void main() {
  vec2 uv = gl_FragCoord.xy / vec2(640.0, 360.0);
  Hit h = trace(vec3(uv, -2.0), vec3(0.0, 0.0, 1.0));
  float d = max(dot(h.n, normalize(light)), 0.0);
  mat3 m = mat3(1.0);
  vec3 c = m * texture(tex, uv).rgb * d + (h.t > 0.0 ? vec3(0.1) : vec3(0.0));
  float bad = 1;
  color = vec4(c, 1.0) * pow(d, 2);
}
