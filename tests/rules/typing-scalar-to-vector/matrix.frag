precision mediump float;
uniform float s;
void main() {
    mat2 m = s;
    m = 2.0;
    gl_FragColor = vec4(m[0], m[1]);
}
