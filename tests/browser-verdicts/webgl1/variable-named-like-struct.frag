precision highp float;
struct d1 { float a; };
void main(){ vec2 a, d1; d1 = vec2(1.0); gl_FragColor = vec4(d1, a); }