// origin: corpus/strict-typing (hand-written), after seeds/000_832ddd5fa6e5b251.txt "GLSL Type Strictness": an int variable assigned to a float
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    int steps = 4;
    float s = steps; // mistake
    fragColor = vec4(floor(uv * s) / s, 0.0, 1.0);
}
