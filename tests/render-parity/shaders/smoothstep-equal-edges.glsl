// smoothstep with equal edges, written out and through a macro (a common golfing
// idiom): GLSL leaves it undefined, GPUs draw a step, llvmpipe's fast math does not.
#define S(x, w) smoothstep(-w, w, x)
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    float a = smoothstep(0.4, 0.4, uv.x);
    float b = S(uv.y - 0.5, 0.0);
    vec3 c = smoothstep(vec3(0.3), vec3(0.3), vec3(uv, uv.x * uv.y));
    fragColor = vec4(a, b, c.z + 0.25 * c.x, 1.0);
}
