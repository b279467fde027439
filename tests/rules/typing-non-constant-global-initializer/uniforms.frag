precision mediump float;
uniform float time;
uniform vec2 resolution;
float t = time * 2.0;
vec2 r = resolution, half_r = r * 0.5;
const float k = 3.0;
float fixed_value = k * 2.0;

void main() { // entry
    gl_FragColor = vec4(t, half_r, fixed_value);
}
