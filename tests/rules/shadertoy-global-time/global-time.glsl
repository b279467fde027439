// Old shaders use iGlobalTime, also inside macros.
#define T (iGlobalTime * 0.5)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(sin(iGlobalTime), cos(T), 0.0, 1.0);
}
