precision mediump float;
#define SCALE 2.0
uniform float t;
void main() {
    float a = t * SCALE;
    float b = SCALE * t;
    gl_FragColor = vec4(a, b, 0.0, 1.0);
}
