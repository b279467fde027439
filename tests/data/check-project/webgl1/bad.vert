attribute vec3 position;
uniform mat4 mvp;
varying vec2 vUv;

void main() {
    vUv = position.xy * 0.5 + 0.5;
    gl_Position = mvp * vec4(position, 1.0);
    gl_PointSize = 1;
}
