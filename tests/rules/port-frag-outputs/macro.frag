precision mediump float;
#define OUT gl_FragColor
void main() {
  OUT = vec4(1.0);
}
