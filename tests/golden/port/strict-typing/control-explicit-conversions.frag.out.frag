#version 300 es
// origin: corpus/strict-typing (hand-written), after seeds/000_832ddd5fa6e5b251.txt "GLSL Type Strictness": control case: int/float mixing written with explicit conversions (valid)
precision highp float;
uniform vec2 resolution;
out vec4 fragColor;
const float kScale = 2.0;

void main() {
    vec2 uv = gl_FragCoord.xy / resolution;
    vec2 p = 2.0 * uv - 1.0;
    float d = max(p.x, 0.0) / 2.0;
    vec3 col = mix(vec3(uv * kScale, 0.0), vec3(1.0), d);
    fragColor = vec4(col, float(1));
}
