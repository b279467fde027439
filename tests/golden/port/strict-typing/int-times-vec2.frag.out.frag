#version 300 es
// origin: corpus/strict-typing (hand-written), after seeds/000_832ddd5fa6e5b251.txt "GLSL Type Strictness": an int literal multiplying a vec2
precision highp float;
uniform vec2 resolution;
out vec4 fragColor;

void main() {
    vec2 uv = gl_FragCoord.xy / resolution;
    vec2 p = 2.0 * uv - 1.0; // mistake
    fragColor = vec4(abs(p), 0.0, 1.0);
}
