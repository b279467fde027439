// Globals without an initializer start at 0 in the browser
// (ANGLE's DeferGlobalInitializers with initializeUninitializedLocals).
vec3 accum;
float total[3];
void add(vec3 c) { accum += c; total[1] += c.g; }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    add(vec3(uv.x, 0.2, uv.y));
    add(vec3(0.1));
    fragColor = vec4(accum, 1.0) + vec4(0.0, total[1] * 0.5, 0.0, 0.0);
}
