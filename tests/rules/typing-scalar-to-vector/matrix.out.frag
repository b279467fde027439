precision mediump float;
uniform float s;
void main() {
    mat2 m = mat2(s);
    m = mat2(2.0);
    gl_FragColor = vec4(m[0], m[1]);
}
