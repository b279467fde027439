// A global named like a built-in function hides it in GLSL ES 3.00.
const int max = 4;
const float step = 0.5;
void mainImage(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(float(max) * step); }
