precision mediump float;
uniform float time;
uniform vec2 resolution;
float t;
vec2 r, half_r;
const float k = 3.0;
float fixed_value = k * 2.0;

void main() { // entry
    t = time * 2.0;
    r = resolution;
    half_r = r * 0.5;
    gl_FragColor = vec4(t, half_r, fixed_value);
}
