"""What shadertoy.com compiles for one pass of any kind: a Python mirror of
src/validate/shadertoy_contract.cpp (ShaderToyHeader, ShaderToyEpilogue,
ComposeShaderToyRequest) for Image, Buffer, Cube A and Sound passes. Keep it in step
with the C++: tests compare the site's verdict on this text with `shaderport check`.

shadertoy_reference.py mirrors the Image pass only (for drawing); this module adds the
other pass kinds and the separator rule for a part ending in a line continuation.
Python 3 standard library only.
"""

from shadertoy_reference import _UNIFORMS

# ChannelTypeFromCtype: everything that is not a cube map or a volume is a sampler2D.
_SAMPLER_BY_CTYPE = {"cubemap": "samplerCube", "volume": "sampler3D"}

# Corpus-record pass type -> model::PassKind name of the C++ (Common is no pass of its own).
PASS_KIND = {"image": "image", "buffer": "buffer", "cube": "cube", "cubemap": "cube",
             "sound": "sound"}


def header(kind, channel_samplers=("sampler2D",) * 4):
    """ShaderToyHeader(kind, channels); kind is image | buffer | cube | sound | common
    (the Common tab compiled on its own: iDate and iSampleRate, no HW_PERFORMANCE)."""
    text = ("#version 300 es\n"
            "#ifdef GL_ES\n"
            "precision highp float;\n"
            "precision highp int;\n"
            "precision mediump sampler3D;\n"
            "#endif\n")
    if kind == "common":
        return text + ("uniform vec4 iDate;\nuniform float iSampleRate;\n"
                       "out vec4 shadertoy_out_color;\n")
    text += _UNIFORMS
    for i, sampler in enumerate(channel_samplers):
        text += "uniform %s iChannel%d;\n" % (sampler, i)
    if kind == "cube":
        text += "uniform vec4 unViewport;\nuniform vec3 unCorners[5];\n"
    if kind == "sound":
        text += "uniform float iTimeOffset;\nuniform int iSampleOffset;\n"
    text += "out vec4 shadertoy_out_color;\n"
    text += "#define HW_PERFORMANCE 1\n"
    return text


def epilogue(kind):
    """ShaderToyEpilogue(kind)."""
    if kind == "common":
        return "void main() {\n  shadertoy_out_color = vec4(0.0);\n}\n"
    if kind == "sound":
        return ("#ifndef mainSound\n"
                "vec2 mainSound(int, float);\n"
                "#endif\n"
                "void main() {\n"
                "  float shadertoy_t = iTimeOffset + ((gl_FragCoord.x - 0.5) + "
                "(gl_FragCoord.y - 0.5) * 512.0) / iSampleRate;\n"
                "  int shadertoy_s = iSampleOffset + int(gl_FragCoord.y - 0.2) * 512 + "
                "int(gl_FragCoord.x - 0.2);\n"
                "  vec2 shadertoy_y = mainSound(shadertoy_s, shadertoy_t);\n"
                "  vec2 shadertoy_v = floor((0.5 + 0.5 * shadertoy_y) * 65536.0);\n"
                "  vec2 shadertoy_vl = mod(shadertoy_v, 256.0) / 255.0;\n"
                "  vec2 shadertoy_vh = floor(shadertoy_v / 256.0) / 255.0;\n"
                "  shadertoy_out_color = vec4(shadertoy_vl.x, shadertoy_vh.x, shadertoy_vl.y, "
                "shadertoy_vh.y);\n"
                "}\n")
    if kind == "cube":
        return ("#ifndef mainCubemap\n"
                "void mainCubemap(out vec4, in vec2, in vec3, in vec3);\n"
                "#endif\n"
                "void main() {\n"
                "  vec4 shadertoy_color = vec4(1e20);\n"
                "  vec3 shadertoy_ro = unCorners[4];\n"
                "  vec2 shadertoy_uv = (gl_FragCoord.xy - unViewport.xy) / unViewport.zw;\n"
                "  vec3 shadertoy_rd = normalize(mix(mix(unCorners[0], unCorners[1], shadertoy_uv.x), "
                "mix(unCorners[3], unCorners[2], shadertoy_uv.x), shadertoy_uv.y) - shadertoy_ro);\n"
                "  mainCubemap(shadertoy_color, gl_FragCoord.xy - unViewport.xy, shadertoy_ro, "
                "shadertoy_rd);\n"
                "  shadertoy_out_color = shadertoy_color;\n"
                "}\n")
    text = ("#ifndef mainImage\n"
            "void mainImage(out vec4, in vec2);\n"
            "#endif\n"
            "void main() {\n"
            "  vec4 shadertoy_color = vec4(1e20);\n"
            "  mainImage(shadertoy_color, gl_FragCoord.xy);\n")
    # Image forces alpha to 1; buffers keep what the shader wrote.
    text += ("  shadertoy_out_color = vec4(shadertoy_color.xyz, 1.0);\n" if kind == "image"
             else "  shadertoy_out_color = shadertoy_color;\n")
    return text + "}\n"


def _user_part(text):
    # A part without a final newline, or ending in a line continuation, would run into
    # the next part's first line, so the C++ adds a "\n" separator after it.
    if (text and text[-1] not in "\r\n") or text.endswith("\\\n") or text.endswith("\\\r\n"):
        return text + "\n"
    return text


def channel_samplers(inputs):
    samplers = ["sampler2D"] * 4
    for inp in inputs or []:
        ch = inp.get("channel", -1)
        if isinstance(ch, int) and 0 <= ch <= 3:
            samplers[ch] = _SAMPLER_BY_CTYPE.get(inp.get("ctype") or inp.get("type") or "",
                                                 "sampler2D")
    return tuple(samplers)


def compose(kind, code, common=None, inputs=()):
    """ComposeShaderToyRequest: header + Common (if any) + pass + epilogue, one text."""
    text = header(kind, channel_samplers(inputs))
    if common is not None:
        text += _user_part(common)
    return text + _user_part(code) + epilogue(kind)


def compose_common_tab(record):
    """The Common tab as the site compiles it on its own, or None without one."""
    common = next((p.get("code", "") for p in record.get("passes") or []
                   if p.get("type") == "common"), None)
    if common is None:
        return None
    return header("common") + _user_part(common) + epilogue("common")


def compose_record(record):
    """[(tab name, kind, fragment text)] for every pass of a corpus record but Common."""
    passes = record.get("passes") or []
    common = next((p.get("code", "") for p in passes if p.get("type") == "common"), None)
    out = []
    for p in passes:
        kind = PASS_KIND.get(p.get("type"))
        if kind:
            out.append((p.get("name"), kind, compose(kind, p.get("code", ""), common,
                                                     p.get("inputs"))))
    return out
