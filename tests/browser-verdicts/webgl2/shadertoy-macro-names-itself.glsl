float line(vec2 p, float a, float b, out float z) { z = 0.0; return length(p) * a * b; }
float _d; float z;
#define line(u,a,b) ( _d = line(u,a,b,z), _d + z )
void mainImage(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(line(fragCoord, 1.0, 2.0)); }
