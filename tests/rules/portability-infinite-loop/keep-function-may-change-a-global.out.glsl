float g = 0.0;
void bump() { g += 0.1; }
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    while (g < 1.0) { bump(); }
    fragColor = vec4(g);
}
