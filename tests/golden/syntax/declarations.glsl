#version 300 es
precision highp float;
layout(std140) uniform Globals { mediump vec4 tint; float weights[3]; } globals;
layout(location = 0) out vec4 fragColor;
flat in int id;
struct Light { vec3 pos; float power; };
struct { Light l[2]; } scene;
const float kTable[3] = float[3](1.0, 2.0, 3.0), kOne = 1.0;
float[2] pair;
invariant gl_Position;
vec3 shade(in Light light, inout vec3 acc, const float k[2]);
