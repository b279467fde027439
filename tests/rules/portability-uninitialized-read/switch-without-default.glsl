void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  int tile = int(fragCoord.x) / 64;
  vec3 col;
  switch (tile) {
    case 0: col = vec3(1.0, 0.0, 0.0); break;
    case 1: col = vec3(0.0, 1.0, 0.0);  // falls through
    case 2: col.b = 1.0; break;
  }
  fragColor = vec4(col, 1.0);
}
