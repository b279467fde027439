precision mediump float;
float c = 1.0;
float f = (c = 0.0);
float g = (c++);
void main() { gl_FragColor = vec4(f + g); }
