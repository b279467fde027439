precision mediump float;
struct S { float t; };
void main() { S a; a.t = 1.0; S b = +a; gl_FragColor = vec4(b.t); }
