float speed = iTime * 0.5;
vec2 res = iResolution.xy;

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / res;
    fragColor = vec4(uv, speed, 1.0);
}
