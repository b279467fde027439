// The entry point is a macro (often in Common): the site's main() calls
// mainImage(color, coord), which this macro turns into a call of Main().
#define mainImage(color, coord) (color = Main(coord / iResolution.xy))

vec4 Main(vec2 uv) {
  return vec4(uv, 0.5, 1.0);
}
