// A struct and an array left uninitialised, filled in part.
struct Hit { float d; vec3 n; int id; };
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    Hit h;
    if (uv.x > 0.5) { h.d = uv.y; h.id = 2; }
    vec3 pts[4];
    pts[1] = vec3(uv, 0.5);
    fragColor = vec4(h.d + pts[0].x, pts[1].y + float(h.id) * 0.1, h.n.z + pts[1].z, 1.0);
}
