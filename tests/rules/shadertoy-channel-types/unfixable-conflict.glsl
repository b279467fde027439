// iChannel2 is sampled both ways: it stays a 2D texture, with a warning.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    fragColor = texture(iChannel2, uv) + textureLod(iChannel2, vec3(uv, 1.0), 0.0);
}
