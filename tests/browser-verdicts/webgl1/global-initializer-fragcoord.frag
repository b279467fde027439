precision mediump float;
// Only uniforms and globals may initialise a global in GLSL ES 1.00, not gl_FragCoord.
float g = gl_FragCoord.x;
void main() { gl_FragColor = vec4(g); }
