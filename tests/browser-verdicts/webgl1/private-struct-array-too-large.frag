precision highp float;
struct S { float a; vec3 b; };
void main() { S s[4096]; s[0].a = 1.0; gl_FragColor = vec4(s[0].a); }
