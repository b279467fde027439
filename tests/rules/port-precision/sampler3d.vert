#version 300 es
uniform sampler3D volume;
in vec3 position;
void main() {
  gl_Position = texture(volume, position);
}
