// Image pass: uses Common's wave().
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = fragCoord / iResolution.xy;
    float v = wave(uv.x + iTime);
    vec3 col = 1.0;
    fragColor = vec4(col * v, 1.0);
}
