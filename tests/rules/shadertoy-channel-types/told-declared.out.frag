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
uniform sampler2D iChannel0;
uniform sampler2D iChannel2;
uniform sampler2D iChannel3;
#define HW_PERFORMANCE 1
precision highp float;
precision highp int;
// channel: 1=cube
// The code declares iChannel1 itself as a 2D texture, but its input is a cube map.
uniform samplerCube iChannel1;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec3 dir = normalize(vec3(fragCoord / iResolution.xy - 0.5, 1.0));
    fragColor = texture(iChannel1, dir);
}

out highp vec4 outColor;
void main() {
  vec4 color = vec4(1e20);
  mainImage(color, gl_FragCoord.xy);
  outColor = vec4(color.xyz, 1.0);
}
