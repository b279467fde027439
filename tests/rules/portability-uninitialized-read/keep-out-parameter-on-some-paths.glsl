bool hitPlane(vec3 ro, vec3 rd, out float t) {
  if (rd.y >= 0.0) return false;
  t = -ro.y / rd.y;
  return true;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  fragColor.rgb = vec3(fragCoord / iResolution.xy, 0.0);
  if (fragCoord.y > 10.0) return;
  float t;
  if (hitPlane(vec3(0.0, 1.0, 0.0), normalize(vec3(fragCoord, -1.0)), t)) fragColor.b = t;
}
