precision mediump float;
uniform sampler2D tex;
uniform samplerCube env;
varying vec2 uv;
void main() {
  vec4 a = texture2D(tex, uv);
  vec4 b = textureCube(env, vec3(uv, 1.0));
  vec4 c = texture2DProj(tex, vec3(uv, 1.0));
  gl_FragColor = a + b + c + texture2D(tex, uv, 1.0);
}
