// NaN in part of the picture (sqrt and log of negative numbers, 0/0).
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy - 0.5;
    float a = sqrt(uv.x);
    float b = log(uv.y);
    float z = uv.x * uv.y;
    fragColor = vec4(a, b, z / z * 0.5, 1.0);
}
