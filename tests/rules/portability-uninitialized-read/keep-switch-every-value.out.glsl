void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  uint bits = uint(fragCoord.x) % 16u;
  float channel;
  switch (bits / 4u) {
    case 0u: channel = 0.1; break;
    case 1u: channel = 0.2; break;
    case 2u: channel = 0.3; break;
    case 3u: channel = 0.4; break;
  }
  fragColor = vec4(channel);
}
