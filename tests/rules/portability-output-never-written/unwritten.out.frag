#version 300 es
precision highp float;
out vec4 color;
void main() {
    vec4 c = vec4(1.0);
}
