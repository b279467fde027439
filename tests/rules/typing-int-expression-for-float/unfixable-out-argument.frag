precision mediump float;
void get(out float v) { v = 1.0; }
void main() {
    int i;
    get(i);
    gl_FragColor = vec4(1.0);
}
