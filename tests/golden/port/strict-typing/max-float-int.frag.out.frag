#version 300 es
// origin: corpus/strict-typing (hand-written), after seeds/000_832ddd5fa6e5b251.txt "GLSL Type Strictness": max() called with a float and an int literal
precision highp float;
uniform vec2 resolution;
out vec4 fragColor;

void main() {
    vec2 uv = gl_FragCoord.xy / resolution - 0.5;
    float d = max(uv.x, 0.0); // mistake
    fragColor = vec4(vec3(d), 1.0);
}
