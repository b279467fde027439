#version 300 es
// A licence header comment.
precision mediump float;
out highp vec4 fragColor;
void main() {
  fragColor = vec4(0.0);
}
