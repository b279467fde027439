void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    float x = 0.0;
    for (;;) {
        for (int i = 0; i < 4; i++) {
            if (x > 1.0) break;
            x += 0.5;
        }
    }
    fragColor = vec4(x);
}
