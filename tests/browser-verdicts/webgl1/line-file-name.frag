precision mediump float;
#line 10 sp_file
void main() { gl_FragColor = vec4(1.0); }
