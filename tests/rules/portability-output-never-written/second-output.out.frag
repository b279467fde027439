#version 300 es
precision highp float;
layout(location = 0) out vec4 albedo;
layout(location = 1) out vec4 normal;
void main() {
    albedo = vec4(1.0);
}
