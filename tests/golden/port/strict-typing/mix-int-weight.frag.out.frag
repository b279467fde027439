#version 300 es
// origin: corpus/strict-typing (hand-written), after seeds/000_832ddd5fa6e5b251.txt "GLSL Type Strictness": mix() called with an int weight
precision highp float;
uniform vec2 resolution;
out vec4 fragColor;

void main() {
    vec2 uv = gl_FragCoord.xy / resolution;
    vec3 col = mix(vec3(uv, 0.0), vec3(1.0), 0.0); // mistake
    fragColor = vec4(col, 1.0);
}
