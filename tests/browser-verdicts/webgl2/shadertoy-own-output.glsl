// The site's own output has no location: a pass cannot add one.
layout(location = 1) out vec4 extra;
void mainImage(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(1.0); extra = fragColor; }
