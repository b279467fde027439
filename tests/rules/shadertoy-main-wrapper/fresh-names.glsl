// The code already uses the names the wrapper would pick, even as a macro.
#define color vec3(1.0, 0.5, 0.0)
float fragColor_1 = 0.0;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(color, 1.0);
}
