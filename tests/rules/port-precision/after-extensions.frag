#version 100
#extension GL_OES_standard_derivatives : enable
#extension GL_EXT_frag_depth : enable // depth
// the varying
varying highp vec2 uv;
void main() {
  gl_FragColor = vec4(fwidth(uv), 0.0, 1.0);
  gl_FragDepthEXT = 0.5;
}
