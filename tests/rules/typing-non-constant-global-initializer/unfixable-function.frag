precision mediump float;
uniform float time;
float wave(float x) { return sin(x); }
float w = wave(time);
const float c = time;
void main() {
    gl_FragColor = vec4(w, c, 0.0, 1.0);
}
