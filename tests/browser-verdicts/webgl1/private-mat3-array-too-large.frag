precision highp float;
// A mat3 is 36 bytes, tightly packed: 1,821 of them pass the limit.
mat3 g[1821];
void main() { g[0] = mat3(1.0); gl_FragColor = vec4(g[0][0], 1.0); }
