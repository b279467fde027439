// iChannel0 is sampled with a direction: a cube map. iChannel1 as a 2D texture.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec3 dir = normalize(vec3(uv * 2.0 - 1.0, 1.0));
    fragColor = texture(iChannel0, dir) * texture(iChannel1, uv);
}
