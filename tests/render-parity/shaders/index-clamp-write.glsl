// A loop index past the end of a vector: the browser clamps it
// (ANGLE's ClampIndirectIndices), so the last component gets every extra write.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec3 col = vec3(0.0);
    for (int c = 0; c < 8; c++) {
        col[c] += 0.1 * uv.x + 0.02 * float(c);
    }
    fragColor = vec4(col * 0.5, 1.0);
}
