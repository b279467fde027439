#version 300 es
uniform highp vec3 iResolution;
uniform highp float iTime;
uniform highp float iChannelTime[4];
uniform highp vec4 iMouse;
uniform highp vec4 iDate;
uniform highp float iSampleRate;
uniform highp vec3 iChannelResolution[4];
uniform highp int iFrame;
uniform highp float iTimeDelta;
uniform highp float iFrameRate;
uniform samplerCube iChannel0;
uniform sampler2D iChannel1;
uniform sampler2D iChannel2;
uniform sampler2D iChannel3;
#define HW_PERFORMANCE 1
precision highp float;
precision highp int;
// iChannel0 is sampled with a direction: a cube map. iChannel1 as a 2D texture.
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    vec3 dir = normalize(vec3(uv * 2.0 - 1.0, 1.0));
    fragColor = texture(iChannel0, dir) * texture(iChannel1, uv);
}

out highp vec4 outColor;
void main() {
  vec4 color = vec4(1e20);
  mainImage(color, gl_FragCoord.xy);
  outColor = vec4(color.xyz, 1.0);
}
