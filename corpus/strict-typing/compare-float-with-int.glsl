// origin: corpus/strict-typing (hand-written), after seeds/000_832ddd5fa6e5b251.txt "GLSL Type Strictness": a float compared with an int literal
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy - 0.5;
    vec3 col = vec3(0.2);
    if (uv.x > 0) { // mistake
        col = vec3(0.8);
    }
    fragColor = vec4(col, 1.0);
}
