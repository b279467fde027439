#version 300 es
uniform highp float u_time;
// dialect: bookofshaders
#ifdef GL_ES
precision mediump float;
#endif
uniform vec2 u_resolution;
out highp vec4 fragColor;
void main() {
    vec2 st = gl_FragCoord.xy / u_resolution;
    fragColor = vec4(st.x, st.y, abs(sin(u_time)), 1.0);
}
