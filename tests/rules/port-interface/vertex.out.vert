#version 300 es
in vec3 position;
in vec2 uv0;
out vec2 uv;
void main() {
  uv = uv0;
  gl_Position = vec4(position, 1.0);
}
