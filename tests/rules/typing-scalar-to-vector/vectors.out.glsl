vec2 zero() { return vec2(0.0); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 col = vec3(1.0);
    col = vec3(0.5 * 2.0);
    vec3 n = vec3(iTime);
    fragColor = vec4(col + n + zero().x, 1.0);
}
