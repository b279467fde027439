void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 v = vec3(1.0, 2.0, 3.0);
    fragColor = vec4(v[1], v[int(iTime) % 3], 0.0, 1.0);
}
