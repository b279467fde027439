precision mediump float;
#define A(s) (s 1.0 + 2.0)
// the only free line above the macro that uses A() is this comment
#define S (A() * A(-))
void main() { gl_FragColor = vec4(S); }
