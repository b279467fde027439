#define T(l) texture(iChannel0, fragCoord / iResolution.xy, l + 0.)
#define M void mainImage(out vec4 O, vec2 fragCoord) { O = T()
M; }
