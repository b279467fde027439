// A pass may declare its own function named texture.
vec3 texture(vec2 p) { return texture(iChannel0, p).rgb; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(texture(fragCoord / iResolution.xy), 1.0); }
