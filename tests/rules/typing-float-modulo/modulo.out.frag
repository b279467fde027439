precision mediump float;
uniform float t;
uniform vec2 p;
void main() {
    float r = mod(t, 2.0);
    vec2 c = mod(p, 3.0);
    float a = t;
    a = mod(a, 0.5);
    gl_FragColor = vec4(r, c, a);
}
