// origin: corpus/strict-typing (hand-written), after seeds/000_832ddd5fa6e5b251.txt "GLSL Type Strictness": control case: the same computations written with explicit conversions (valid)
float brightness() {
    return 1.0;
}

float halve(float v) {
    return v * 0.5;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    int steps = 4;
    float s = float(steps);
    vec3 col = vec3(1) * uv.x;
    float x = float(1);
    float y = pow(uv.x, 2.0) + uv.y * 2.0 + halve(1.0) * brightness();
    float k = uv.x > 0.5 ? 1.0 : 0.5;
    if (uv.x > 0.0) {
        col += vec3(0.1);
    }
    col = clamp(col + x * y * k, 0.0, 1.0);
    fragColor = vec4(floor(col * s) / s, 1.0);
}
