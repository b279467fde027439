// ... but not a redefinition with the built-in's own parameters.
precision mediump float;
float sin(float x) { return x; }
void main() { gl_FragColor = vec4(sin(1.0)); }
