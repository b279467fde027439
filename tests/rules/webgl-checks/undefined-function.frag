precision mediump float;
// noise is declared but never defined.
float noise(vec2 p);
void main() { gl_FragColor = vec4(noise(gl_FragCoord.xy)); }
