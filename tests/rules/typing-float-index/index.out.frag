precision mediump float;
uniform float w[4];
void main() {
    float s = 0.0;
    for (float i = 0.0; i < 4.0; i += 1.0) {
        s += w[int(i)];
    }
    vec3 v = vec3(1.0, 2.0, 3.0);
    gl_FragColor = vec4(s, v[1], v[int(2.0)], 1.0);
}
