// Writes the colour as a vec3 varying; the fragment shader reads it as a vec4.
attribute vec4 position;
attribute vec3 color;
varying vec3 vColor;
void main() { vColor = color; gl_Position = position; }
