void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec3 col = vec3(0.0);
    for (int i = 0; iTime > 0.0; ) {
        col += 0.01;
    }
    fragColor = vec4(col, 1.0);
}
