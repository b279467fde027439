void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float acc = 0.0;
    for (float i = 0.0; i < 4.0; i += 1.0) {
        acc += i / 4.0;
    }
    fragColor = vec4(vec3(acc), 1.0);
}
