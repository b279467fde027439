// The bound is a global constant and the body calls only built-ins and
// constructors, which change nothing: the loop still never ends.
const int ITERATIONS = 6;
vec3 fold = vec3(0.46, 0.35, 0.76);
float kset(vec3 p)
{
    float m = 1000.0;
    for (int i = 0; i < ITERATIONS; ) {
        float d = dot(p, p);
        p = abs(p) / d - vec3(fold);
        m = min(m, abs(d - 0.5));
    }
    return m;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    fragColor = vec4(kset(vec3(fragCoord, 1.0)));
}
