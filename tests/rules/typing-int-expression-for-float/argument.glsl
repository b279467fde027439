float halve(float v) { return v * 0.5; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float f = halve(iFrame) + max(iTime, iFrame % 60);
    fragColor = vec4(vec3(f), 1.0);
}
