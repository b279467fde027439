struct Ray { vec3 origin; vec3 direction; };

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  float weights[3];
  weights[0] = 0.25;
  Ray ray;
  ray.origin = vec3(0.0);
  mat2 m;
  m[0] = vec2(1.0, 0.0);
  fragColor = vec4(weights[1], ray.direction.x, m[1]);
}
