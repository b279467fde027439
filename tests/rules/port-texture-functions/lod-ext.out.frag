#version 300 es
precision mediump float;
uniform sampler2D tex;
in vec2 uv;
out highp vec4 fragColor;
void main() {
  fragColor = textureLod(tex, uv, 2.0) +
                 textureGrad(tex, uv, dFdx(uv), dFdy(uv));
}
