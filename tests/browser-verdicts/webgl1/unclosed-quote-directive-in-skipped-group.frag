precision mediump float;
#if 0
#"
#define X "
#endif
void main() { gl_FragColor = vec4(1.0); }
