#!/usr/bin/env python3
"""Wraps ShaderToy pass code in shadertoy.com's WebGL2 page header so glslangValidator can
check it as a GLSL ES 3.00 fragment shader.

The header follows the site contract described in shared/notes/peers-and-users.md section 1c:
version and precision lines, the uniforms, one sampler per channel typed from the pass inputs,
HW_PERFORMANCE, the mainImage prototype, then Common + the pass, then main().

Usage as a script: shadertoy_wrap.py IN.glsl OUT.frag [CTYPE0 CTYPE1 CTYPE2 CTYPE3]
"""
import sys

_SAMPLER_BY_CTYPE = {"cubemap": "samplerCube", "volume": "sampler3D"}

_HEADER = """#version 300 es
#ifdef GL_ES
precision highp float;
precision highp int;
precision mediump sampler3D;
#endif
#define HW_PERFORMANCE 1
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
{samplers}
void mainImage(out vec4 c, in vec2 f);
"""

_FOOTER = """
out vec4 shadertoy_out_color;
void main(void) {
  shadertoy_out_color = vec4(1.0, 1.0, 1.0, 1.0);
  vec4 color = vec4(1e20);
  mainImage(color, gl_FragCoord.xy);
  shadertoy_out_color = vec4(color.xyz, 1.0);
}
"""


def header(ctypes=()):
  """The text placed before the user's code; ctypes[i] is channel i's input type."""
  ctypes = list(ctypes) + [""] * (4 - len(ctypes))
  samplers = "\n".join("uniform %s iChannel%d;" % (_SAMPLER_BY_CTYPE.get(c, "sampler2D"), i)
                       for i, c in enumerate(ctypes[:4]))
  return _HEADER.replace("{samplers}", samplers)


def wrap(code, common="", ctypes=()):
  """Whole fragment shader text: header + Common + pass code + main().

  #line directives make glslang report lines of the user's own text: source string 1 is
  Common, source string 0 the pass (ESSL 3.00: the line after `#line N` is line N).
  """
  text = header(ctypes)
  if common:
    text += "#line 1 1\n" + common + "\n"
  return text + "#line 1 0\n" + code + "\n" + _FOOTER


if __name__ == "__main__":
  if len(sys.argv) < 3:
    sys.exit("usage: shadertoy_wrap.py IN.glsl OUT.frag [CTYPE0..3]")
  with open(sys.argv[1]) as f:
    text = f.read()
  with open(sys.argv[2], "w") as f:
    f.write(wrap(text, ctypes=sys.argv[3:]))
