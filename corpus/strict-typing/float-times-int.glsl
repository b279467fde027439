// origin: corpus/strict-typing (hand-written), after seeds/000_832ddd5fa6e5b251.txt "GLSL Type Strictness": a float multiplied by an int literal
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    float x = uv.x;
    float y = x * 2; // mistake
    fragColor = vec4(vec3(y), 1.0);
}
