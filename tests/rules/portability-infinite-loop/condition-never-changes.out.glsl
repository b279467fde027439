void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    float t = 0.0;
    vec3 p = vec3(fragCoord, 1.0);
    while (t < 10.0) {
        p += 0.1;   // the march forgot to advance t
    }
    fragColor = vec4(p, 1.0);
}
