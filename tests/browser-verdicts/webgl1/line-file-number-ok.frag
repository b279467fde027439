precision mediump float;
#line 10 2 // source string 2
void main() { gl_FragColor = vec4(1.0); }
