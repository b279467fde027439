void advance(inout float t) { t += 0.5; }
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    float t = 0.0, u = 0.0;
    while (t < 10.0) { t += 0.1; }
    while (u < 10.0) { advance(u); }
    for (float v = 0.0; v < 1.0; v += 0.25) { fragColor.x = v; }
    int i = 0;
    do { i++; } while (i < 3);
    fragColor = vec4(t + u);
}
