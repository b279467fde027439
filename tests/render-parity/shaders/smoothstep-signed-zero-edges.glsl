// smoothstep(-w, w, x) with w = 0.5 * fwidth(c) of a value constant across the quad:
// fwidth is -0.0 there in browsers, so the edges are +0.0 and -0.0, (x - a) / (b - a)
// is -inf where x > 0 and +inf where x < 0, and the step is turned round.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy - 0.5;
    float c = floor(fragCoord.x / 16.0);
    float w = 0.5 * fwidth(c);
    float a = smoothstep(-w, w, uv.x);
    vec2 b = smoothstep(vec2(-w), vec2(w), uv.yx);
    fragColor = vec4(a, b.x, 0.5 * b.y + 0.25, 1.0);
}
