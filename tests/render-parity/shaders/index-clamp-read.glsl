// Reads past both ends of an array and a matrix, with indices from the picture.
const float ramp[4] = float[4](0.1, 0.35, 0.6, 0.85);
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    int i = int(fragCoord.x / iResolution.x * 8.0) - 2;  // -2 .. 5
    int j = int(fragCoord.y / iResolution.y * 6.0);      //  0 .. 5
    mat3 m = mat3(0.2, 0.4, 0.6, 0.3, 0.5, 0.7, 0.9, 0.8, 0.1);
    float r = ramp[i];
    float g = m[j][1];
    float b = m[1][j];
    fragColor = vec4(r, g, b, 1.0);
}
