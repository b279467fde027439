// A local read before any write: browsers start it at 0 (ANGLE's
// InitializeUninitializedLocals); native drivers leave it undefined.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec4 col;
    col += vec4(uv, 0.5, 1.0);
    float s;
    for (int i = 0; i < 4; i++) s += 0.1 * uv.x;
    fragColor = col + vec4(s);
}
