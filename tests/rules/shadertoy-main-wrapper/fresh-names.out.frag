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
uniform sampler2D iChannel1;
uniform sampler2D iChannel2;
uniform sampler2D iChannel3;
#define HW_PERFORMANCE 1
precision highp float;
precision highp int;
// The code already uses the names the wrapper would pick, even as a macro.
#define color vec3(1.0, 0.5, 0.0)
float fragColor_1 = 0.0;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    fragColor = vec4(color, 1.0);
}

out highp vec4 outColor;
void main() {
  vec4 color_1 = vec4(1e20);
  mainImage(color_1, gl_FragCoord.xy);
  outColor = vec4(color_1.xyz, 1.0);
}
