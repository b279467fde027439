// channel: 1=cube
// The code declares iChannel1 itself as a 2D texture, but its input is a cube map.
uniform sampler2D iChannel1;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 dir = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));
    fragColor = texture(iChannel1, dir);
}
