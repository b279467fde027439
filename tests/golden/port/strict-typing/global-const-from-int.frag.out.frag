#version 300 es
// origin: corpus/strict-typing (hand-written), after seeds/000_832ddd5fa6e5b251.txt "GLSL Type Strictness": a global const float initialised from an int literal
precision highp float;
uniform vec2 resolution;
out vec4 fragColor;
const float kScale = 2.0; // mistake

void main() {
    vec2 uv = gl_FragCoord.xy / resolution;
    fragColor = vec4(uv * kScale, 0.0, 1.0);
}
