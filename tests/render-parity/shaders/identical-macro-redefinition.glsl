// The same macro defined twice, identically (legal), with a built-in in its body that
// render renames (smoothstep): the rename must reach both definitions, or Mesa refuses
// the redefinition and nothing is drawn (ShaderToy tlXfDS).
#define S(a, b, c) smoothstep(a, b, c)
float Ramp(float x) { return S(0.2, 0.8, x); }
#define S(a, b, c) smoothstep(a, b, c)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    fragColor = vec4(S(0.3, 0.3, uv.x), Ramp(uv.y), sin(uv.x * 6.0) * 0.5 + 0.5, 1.0);
}
