void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    float x = 0.0;
    for (;;) {
        if (x > 1.0) break;
        x += 0.1;
    }
    fragColor = vec4(x);
}
