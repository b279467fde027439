#version 300 es
uniform highp float time;
uniform highp vec2 mouse;
uniform highp vec2 resolution;
// A glslsandbox.com paste: the page provides time, mouse and resolution, and
// this snippet never declares them.
#ifdef GL_ES
precision mediump float;
#endif

out highp vec4 fragColor;
void main(void) {
	vec2 p = (gl_FragCoord.xy / resolution.xy) - 0.5;
	p.x *= resolution.x / resolution.y;
	float d = length(p - (mouse - 0.5));
	float c = sin(p.x * 10.0 + time) + cos(p.y * 12.0 - time * 1.3);
	c += sin(d * 30.0 - time * 4.0);
	fragColor = vec4(0.5 + 0.5 * cos(c + vec3(0.0, 2.0, 4.0)), 1.0);
}
