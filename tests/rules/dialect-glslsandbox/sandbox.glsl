// dialect: glslsandbox
#ifdef GL_ES
precision mediump float;
#endif
uniform float time;
uniform vec2 resolution;
void main(void) {
    vec2 position = gl_FragCoord.xy / resolution.xy + mouse / 4.0;
    float color = sin(position.x * cos(time / 15.0) * 80.0);
    gl_FragColor = vec4(vec3(color, color * 0.5, sin(color + time / 3.0) * 0.75), 1.0);
}
