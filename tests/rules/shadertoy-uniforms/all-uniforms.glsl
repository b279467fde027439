// Uses a few of the site's uniforms; all are declared, as the site does.
#if HW_PERFORMANCE == 0
#define STEPS 32
#else
#define STEPS 64
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (fragCoord - 0.5 * iResolution.xy) / iResolution.y;
    float t = iTime + float(iFrame) * iTimeDelta;
    vec3 col = vec3(0.0);
    for (int i = 0; i < STEPS; i++) col += 0.01 * cos(t + uv.xyx + float(i));
    fragColor = vec4(col + iMouse.xyz / iResolution.xyx, 1.0);
}
