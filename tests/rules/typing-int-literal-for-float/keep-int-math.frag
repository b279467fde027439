precision mediump float;
void main() {
    int n = 3 * 2;
    vec3 c = vec3(1, 0, n);
    gl_FragColor = vec4(c, 1.0);
}
