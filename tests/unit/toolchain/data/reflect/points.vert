#version 300 es
// A vertex shader with explicit and automatic attribute locations.
layout(location = 3) in vec3 position;
in vec4 color;
in float size;
uniform mat4 modelViewProjection;
uniform float pointScale;
out vec4 v_color;
flat out int v_instance;

void main() {
  v_color = color;
  v_instance = gl_InstanceID;
  gl_PointSize = size * pointScale;
  gl_Position = modelViewProjection * vec4(position, 1.0);
}
