float march(vec3 p)
{
    for (;;) {
        if (length(p) < 1.0) return length(p);
        p *= 0.9;
    }
}
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    while (true) {
        if (fragCoord.x > 10.0) discard;
        fragCoord.x += 1.0;
    }
    fragColor = vec4(march(vec3(fragCoord, 1.0)));
}
