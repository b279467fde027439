void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 p = fragCoord;
    for (;;) {
        p *= 1.01;
    }
    fragColor = vec4(p, 0.0, 1.0);
}
