precision mediump float;
uniform vec4 u[4];
uniform int k;
void main() { gl_FragColor = u[k]; }
