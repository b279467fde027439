// origin: corpus/strict-typing (hand-written), after seeds/000_832ddd5fa6e5b251.txt "GLSL Type Strictness": a ternary whose branches are an int and a float
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    float k = uv.x > 0.5 ? 1 : 0.5; // mistake
    fragColor = vec4(vec3(k), 1.0);
}
