precision mediump float;
uniform float t;
float halve(float x) { return x * 0.5; }
float one() { return 1; }
struct S { float a; };
void main() {
    float x = 1;
    x = 0x10;
    bool b = t > 0 && t <= -3;
    float y = b ? 2 : t;
    float z = halve(4) + pow(x, 2) + clamp(t, 0, 1);
    S s = S(2);
    gl_FragColor = vec4(x, y, z + s.a + one(), 1);
}
