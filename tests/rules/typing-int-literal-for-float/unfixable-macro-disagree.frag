precision mediump float;
#define N 4
uniform float t;
void main() {
    float a = t * N;
    int k = N;
    gl_FragColor = vec4(a, float(k), 0.0, 1.0);
}
