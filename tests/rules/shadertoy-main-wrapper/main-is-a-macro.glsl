// A golfing idiom: the user's own main() is mainImage under a macro.
#define main() mainImage(out vec4 fragColor, in vec2 fragCoord)
#define R iResolution

void main() {
  fragColor = vec4(fragCoord / R.xy, 0.5, 1.0);
}
