// glslang defines GL_OES_standard_derivatives in GLSL ES 3.00; browsers and shaderport do not.
float aastep(float t, float v) {
  #ifdef GL_OES_standard_derivatives
    float w = fwidth(v);
    return smoothstep(t - w, t + w, v);
  #else
    return step(t, v);
  #endif
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(aastep(0.5, fragCoord.x)); }
