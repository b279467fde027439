// Control: initialised variables and in-range indices, drawn the same everywhere.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec3 col = vec3(0.0);
    for (int c = 0; c < 3; c++) col[c] = 0.25 * float(c) + 0.5 * uv.x * uv.y;
    fragColor = vec4(col, 1.0);
}
