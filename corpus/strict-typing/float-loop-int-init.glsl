// origin: corpus/strict-typing (hand-written), after seeds/000_832ddd5fa6e5b251.txt "GLSL Type Strictness": a float loop counter initialised from an int literal
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    float acc = 0.0;
    for (float i = 0; i < 4.0; i += 1.0) { // mistake
        acc += 0.25 * sin(uv.x * i);
    }
    fragColor = vec4(vec3(acc), 1.0);
}
