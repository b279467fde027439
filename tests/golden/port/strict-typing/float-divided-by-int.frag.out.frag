#version 300 es
// origin: corpus/strict-typing (hand-written), after seeds/000_832ddd5fa6e5b251.txt "GLSL Type Strictness": a float divided by an int literal
precision highp float;
uniform vec2 resolution;
out vec4 fragColor;

void main() {
    vec2 uv = gl_FragCoord.xy / resolution;
    float half_x = uv.x / 2.0; // mistake
    fragColor = vec4(vec3(half_x), 1.0);
}
