// The user's `precision mediump float;` overrides the site's highp. Desktop browsers
// compute mediump at 32 bits; Mesa at 16, where 311000.0 overflows to infinity.
precision mediump float;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    float time = (310.0 + iTime) * 1000.0;
    vec2 p = vec2(0.5 + 0.5 * sin(time / 9000.0), 0.5 + 0.5 * sin(time / 7100.0));
    float d = length(uv - p);
    fragColor = vec4(vec3(smoothstep(0.3, 0.25, d)) * vec3(uv, 1.0), 1.0);
}
