// Macros glslang's preprocessor crashes on (conformance macro-expansion-tricky), and a
// type error only glslang would see: check compiles its own expansion with glslang then.
#define m(a)
#define a m((a)
a)

precision mediump float;
struct S { float x; };

void main() {
    gl_FragColor = vec4(0.0); S s; s++;
}
