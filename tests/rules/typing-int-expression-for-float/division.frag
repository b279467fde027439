precision mediump float;
uniform float t;
void main() {
    int i = 3;
    float x = 1 / 2;
    float y = t * i;
    vec2 p = vec2(1.0, 2.0) + ivec2(i, 2);
    float z = (i + 1);
    gl_FragColor = vec4(x, y, p.x + z, 1.0);
}
