precision mediump float;
uniform sampler2D s;
float f = texture2D(s, vec2(0.5)).x;
void main() { gl_FragColor = vec4(f); }
