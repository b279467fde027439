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
uniform highp float iTimeOffset;
uniform highp int iSampleOffset;
#define HW_PERFORMANCE 1
precision highp float;
precision highp int;
// A Sound pass: mainSound returns the stereo sample at a time.
vec2 mainSound(int samp, float time) {
    return vec2(sin(6.2831 * 440.0 * time) * exp(-3.0 * time));
}

out highp vec4 outColor;
void main() {
  float t = iTimeOffset + ((gl_FragCoord.x - 0.5) + (gl_FragCoord.y - 0.5) * 512.0) / iSampleRate;
  int s = iSampleOffset + int(gl_FragCoord.y - 0.2) * 512 + int(gl_FragCoord.x - 0.2);
  vec2 y = mainSound(s, t);
  vec2 v = floor((0.5 + 0.5 * y) * 65536.0);
  vec2 vl = mod(v, 256.0) / 255.0;
  vec2 vh = floor(v / 256.0) / 255.0;
  outColor = vec4(vl.x, vh.x, vl.y, vh.y);
}
