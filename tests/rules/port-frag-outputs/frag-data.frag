#extension GL_EXT_draw_buffers : require
precision mediump float;
const int kNormal = 1;
void main() {
  gl_FragData[0] = vec4(1.0);
  gl_FragData[kNormal] = vec4(0.5);
  gl_FragData[(1)].a = 1.0;
}
