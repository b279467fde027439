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
// The entry point is a macro (often in Common): the site's main() calls
// mainImage(color, coord), which this macro turns into a call of Main().
#define mainImage(color, coord) (color = Main(coord / iResolution.xy))

vec4 Main(vec2 uv) {
  return vec4(uv, 0.5, 1.0);
}

out highp vec4 outColor;
void main() {
  vec4 color_1 = vec4(1e20);
  mainImage(color_1, gl_FragCoord.xy);
  outColor = vec4(color_1.xyz, 1.0);
}
