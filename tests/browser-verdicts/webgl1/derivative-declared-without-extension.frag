precision mediump float;
// Without GL_OES_standard_derivatives browsers have no dFdx: a shader may declare one.
float dFdx(vec2 r) { return r.x; }
void main() { gl_FragColor = vec4(dFdx(vec2(0.5))); }
