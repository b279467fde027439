void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    float x = 0.0;
    do { x += 0.1; } while (true);
    fragColor = vec4(x);
}
