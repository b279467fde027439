precision mediump float;
#line 4294967296
void main() { gl_FragColor = vec4(1.0); }
