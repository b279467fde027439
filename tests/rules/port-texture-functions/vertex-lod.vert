attribute vec2 p;
uniform sampler2D height;
void main() {
  gl_Position = vec4(p, texture2DLod(height, p, 0.0).r, 1.0);
}
