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
uniform highp vec4 unViewport;
uniform highp vec3 unCorners[5];
#define HW_PERFORMANCE 1
precision highp float;
precision highp int;
// A Cubemap pass gets the site's viewport and corner uniforms too.
void mainCubemap(out vec4 fragColor, in vec2 fragCoord, in vec3 rayOri, in vec3 rayDir) {
    fragColor = vec4(0.5 + 0.5 * rayDir, 1.0);
}

out highp vec4 outColor;
void main() {
  vec4 color = vec4(1e20);
  vec3 ro = unCorners[4];
  vec2 uv = (gl_FragCoord.xy - unViewport.xy) / unViewport.zw;
  vec3 rd = normalize(mix(mix(unCorners[0], unCorners[1], uv.x), mix(unCorners[3], unCorners[2], uv.x), uv.y) - ro);
  mainCubemap(color, gl_FragCoord.xy - unViewport.xy, ro, rd);
  outColor = color;
}
