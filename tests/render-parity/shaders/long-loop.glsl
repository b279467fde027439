// 100000 iterations per pixel: browsers run them all; llvmpipe stops at 65535,
// which `render` reports as render/loop-cap instead of drawing a wrong picture silently.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float c = 0.0;
    for (int i = 0; i < 100000; i++) c += 1.0;
    fragColor = vec4(c / 100000.0, fragCoord / iResolution.xy, 1.0);
}
