// origin: corpus/strict-typing (hand-written), after seeds/000_832ddd5fa6e5b251.txt "GLSL Type Strictness": clamp() called on a float with int bounds
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    float x = clamp(uv.x * 2.0, 0, 1); // mistake
    fragColor = vec4(vec3(x), 1.0);
}
