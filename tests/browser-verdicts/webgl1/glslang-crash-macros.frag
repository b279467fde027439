// Macros glslang's preprocessor crashes on: the same file without an error compiles.
#define m(a)
#define a m((a)
a)

precision mediump float;

void main() {
    gl_FragColor = vec4(0.0);
}
