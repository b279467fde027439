#version 300 es
precision mediump float;
const int kNormal = 1;
layout(location = 0) out highp vec4 fragData0;
layout(location = 1) out highp vec4 fragData1;
void main() {
  fragData0 = vec4(1.0);
  fragData1 = vec4(0.5);
  fragData1.a = 1.0;
}
