#extension GL_OES_standard_derivatives : enable
#extension GL_EXT_shader_texture_lod : require // lod
precision mediump float;
varying vec2 uv;
void main() {
  gl_FragColor = vec4(dFdx(uv), 0.0, 1.0);
}
