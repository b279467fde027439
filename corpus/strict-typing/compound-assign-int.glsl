// origin: corpus/strict-typing (hand-written), after seeds/000_832ddd5fa6e5b251.txt "GLSL Type Strictness": an int literal added to a float with +=
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    float t = iTime;
    t += 1; // mistake
    fragColor = vec4(uv, 0.5 + 0.5 * sin(t), 1.0);
}
