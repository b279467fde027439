precision mediump float;
attribute vec4 a_pos;
varying vec2 v_uv;
uniform sampler2D u_tex;
void main(void) {
  v_uv = a_pos.xy * 0.5 + 0.5;
  gl_Position = vec4(a_pos.xyz, 1.0);
  gl_FragColor = texture2D(u_tex, v_uv).rgba;
}
