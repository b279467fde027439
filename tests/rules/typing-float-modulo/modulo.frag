precision mediump float;
uniform float t;
uniform vec2 p;
void main() {
    float r = t % 2.0;
    vec2 c = p % 3;
    float a = t;
    a %= 0.5;
    gl_FragColor = vec4(r, c, a);
}
