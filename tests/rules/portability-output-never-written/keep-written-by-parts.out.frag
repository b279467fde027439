#version 300 es
precision highp float;
out vec4 color;
void main() {
    color.rgb = vec3(0.25);
    color.a = 1.0;
}
