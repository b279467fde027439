// channel: 1=3d
// Told that iChannel1 is a volume: sampler3D, with the site's mediump.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 p = vec3(fragCoord / iResolution.xy, fract(iTime));
    fragColor = texture(iChannel1, p);
}
