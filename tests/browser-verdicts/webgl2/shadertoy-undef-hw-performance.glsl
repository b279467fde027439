// The site's HW_PERFORMANCE is a plain #define of its header.
#undef HW_PERFORMANCE
#define HW_PERFORMANCE 0
void mainImage(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(float(HW_PERFORMANCE)); }
