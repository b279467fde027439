precision mediump float;
uniform float t;
void main() {
    float a[2];
    a[0] = t;
    a[1] = t;
    int i = 0;
    a[i++] %= 2.0;
    gl_FragColor = vec4(a[0], 1.0 % vec2(t), 1.0);
}
