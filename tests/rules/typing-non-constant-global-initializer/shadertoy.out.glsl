float speed;
vec2 res;

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    speed = iTime * 0.5;
    res = iResolution.xy;
    vec2 uv = fragCoord / res;
    fragColor = vec4(uv, speed, 1.0);
}
