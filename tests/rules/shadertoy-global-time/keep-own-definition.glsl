// The code defines iGlobalTime itself: left alone.
#define iGlobalTime iTime
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(sin(iGlobalTime), 0.0, 0.0, 1.0);
}
