precision mediump float;
uniform float t;
float halve(float x) { return x * 0.5; }
float one() { return 1.0; }
struct S { float a; };
void main() {
    float x = 1.0;
    x = 16.0;
    bool b = t > 0.0 && t <= -3.0;
    float y = b ? 2.0 : t;
    float z = halve(4.0) + pow(x, 2.0) + clamp(t, 0.0, 1.0);
    S s = S(2.0);
    gl_FragColor = vec4(x, y, z + s.a + one(), 1);
}
