precision mediump float;
#define __FILE__ 1
void main() { gl_FragColor = vec4(1.0); }
