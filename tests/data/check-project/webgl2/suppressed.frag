#version 300 es
precision highp float;
out vec4 color;
uniform float time;

void main() {
    float a = 1; // shaderport-ignore(glslang/type-mismatch)
    // shaderport-ignore-next-line(glslang/undeclared-identifier)
    float b = 2.0;
    color = vec4(a, b, time, 1.0);
}
