#version 300 es
precision highp float;
out vec4 color;
void main() {
    float x = 0.0;
    while (true) { x += 0.1; }
    color = vec4(x);
}
