vec2 zero() { return 0.0; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 col = 1.0;
    col = 0.5 * 2;
    vec3 n = iTime;
    fragColor = vec4(col + n + zero().x, 1.0);
}
