// the site compiles this pass behind its header: __LINE__ counts those lines too
#if __LINE__ < 10
uniform float iTime;
#endif
void mainImage(out vec4 o, in vec2 u) { o = vec4(iTime); }
