precision mediump float;
// A backslash continues a line in GLSL ES 1.00 too.
#define TWO 1.0 \
  + 1.0
float y = 1.0; \

void main() { gl_FragColor = vec4(TWO * y); }
