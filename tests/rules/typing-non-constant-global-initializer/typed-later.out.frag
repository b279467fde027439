precision mediump float;
uniform float time;
float a;
float b;
void main() {
    a = time;
    b = a * 2.0;
    gl_FragColor = vec4(a, b, 0.0, 1.0);
}
