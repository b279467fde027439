#extension GL_EXT_shader_texture_lod : enable
#extension GL_OES_standard_derivatives : enable
precision mediump float;
uniform sampler2D tex;
varying vec2 uv;
void main() {
  gl_FragColor = texture2DLodEXT(tex, uv, 2.0) +
                 texture2DGradEXT(tex, uv, dFdx(uv), dFdy(uv));
}
