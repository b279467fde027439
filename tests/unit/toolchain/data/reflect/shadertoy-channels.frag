#version 300 es
// A ShaderToy pass whose channels are a 2D buffer, a cubemap, a volume and nothing.
precision highp float;
precision highp int;
precision mediump sampler3D;
uniform vec3 iResolution;
uniform float iTime;
uniform float iChannelTime[4];
uniform vec4 iMouse;
uniform vec4 iDate;
uniform float iSampleRate;
uniform vec3 iChannelResolution[4];
uniform int iFrame;
uniform float iTimeDelta;
uniform float iFrameRate;
uniform sampler2D iChannel0;
uniform samplerCube iChannel1;
uniform sampler3D iChannel2;
uniform sampler2D iChannel3;
void mainImage(out vec4 c, in vec2 f);

vec3 sky(vec3 direction) { return textureLod(iChannel1, direction, 0.0).rgb; }

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = fragCoord / iResolution.xy;
  vec4 previous = texelFetch(iChannel0, ivec2(fragCoord), 0);
  vec3 fog = texture(iChannel2, vec3(uv, iTime * 0.1)).rgb;
  vec3 color = mix(sky(vec3(uv - 0.5, 1.0)), fog, iMouse.x / iResolution.x);
  fragColor = vec4(mix(color, previous.rgb, 0.9), 1.0);
}

out vec4 shadertoy_out_color;
void main() {
  vec4 color = vec4(1e20);
  mainImage(color, gl_FragCoord.xy);
  shadertoy_out_color = vec4(color.xyz, 1.0);
}
