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
// Uses a few of the site's uniforms; all are declared, as the site does.
#if HW_PERFORMANCE == 0
#define STEPS 32
#else
#define STEPS 64
#endif
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (fragCoord - 0.5 * iResolution.xy) / iResolution.y;
    float t = iTime + float(iFrame) * iTimeDelta;
    vec3 col = vec3(0.0);
    for (int i = 0; i < STEPS; i++) col += 0.01 * cos(t + uv.xyx + float(i));
    fragColor = vec4(col + iMouse.xyz / iResolution.xyx, 1.0);
}

out highp vec4 outColor;
void main() {
  vec4 color = vec4(1e20);
  mainImage(color, gl_FragCoord.xy);
  outColor = vec4(color.xyz, 1.0);
}
