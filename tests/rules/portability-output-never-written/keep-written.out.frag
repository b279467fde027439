#version 300 es
precision highp float;
out vec4 color;
void paint(out vec4 c) { c = vec4(0.5); }
void main() {
    paint(color);
}
