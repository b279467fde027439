// origin: corpus/strict-typing (hand-written), after seeds/000_832ddd5fa6e5b251.txt "GLSL Type Strictness": an int passed to a float parameter
float halve(float v) {
    return v * 0.5;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    float h = halve(1); // mistake
    fragColor = vec4(uv * h, 0.0, 1.0);
}
