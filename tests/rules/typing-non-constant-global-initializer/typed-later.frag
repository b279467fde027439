precision mediump float;
uniform float time;
float a = time;
float b = a * 2;
void main() {
    gl_FragColor = vec4(a, b, 0.0, 1.0);
}
