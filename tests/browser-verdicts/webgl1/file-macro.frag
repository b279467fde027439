precision mediump float;
void main() { int f = __FILE__; gl_FragColor = vec4(float(f)); }
