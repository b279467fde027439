"""Minimal PNG reading and writing with the Python standard library (zlib + struct).

Reads 8-bit, non-interlaced PNGs of colour type 0 (grey), 2 (RGB), 4 (grey+alpha) and
6 (RGBA), which covers what `shaderport render` and tools/browser write. Writes 8-bit RGBA.
Images are (width, height, pixels) with pixels a bytes object of width*height*4 RGBA
bytes, rows top-down.

Used by shadertoy_reference.py (writer), compare_pictures.py (reader) and
measure_render_parity.py (both).
"""

import struct
import zlib

_SIGNATURE = b"\x89PNG\r\n\x1a\n"


class PngError(ValueError):
    pass


def _chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def encode_png(width, height, rgba):
    """PNG bytes for `rgba` (width*height*4 bytes, rows top-down)."""
    if len(rgba) != width * height * 4:
        raise PngError("pixel buffer has %d bytes, expected %d" % (len(rgba), width * height * 4))
    stride = width * 4
    raw = bytearray()
    for y in range(height):
        raw.append(0)  # filter: none
        raw += rgba[y * stride:(y + 1) * stride]
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return (_SIGNATURE + _chunk(b"IHDR", ihdr) + _chunk(b"IDAT", zlib.compress(bytes(raw), 9)) +
            _chunk(b"IEND", b""))


def write_png(path, width, height, rgba):
    with open(path, "wb") as f:
        f.write(encode_png(width, height, rgba))


def _paeth(a, b, c):
    p = a + b - c
    pa = abs(p - a)
    pb = abs(p - b)
    pc = abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    if pb <= pc:
        return b
    return c


def decode_png(data):
    """(width, height, rgba bytes top-down) from PNG bytes."""
    if data[:8] != _SIGNATURE:
        raise PngError("not a PNG file")
    pos = 8
    width = height = None
    depth = ctype = interlace = None
    idat = bytearray()
    while pos + 8 <= len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind = data[pos + 4:pos + 8]
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            width, height, depth, ctype, _comp, _filt, interlace = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            break
    if width is None:
        raise PngError("no IHDR chunk")
    if depth != 8:
        raise PngError("only 8-bit PNGs are supported (bit depth %d)" % depth)
    if interlace != 0:
        raise PngError("interlaced PNGs are not supported")
    channels = {0: 1, 2: 3, 4: 2, 6: 4}.get(ctype)
    if channels is None:
        raise PngError("unsupported colour type %d (palette PNGs are not supported)" % ctype)
    raw = zlib.decompress(bytes(idat))
    stride = width * channels
    if len(raw) < height * (stride + 1):
        raise PngError("truncated image data")
    out = bytearray(height * stride)
    prev = bytearray(stride)
    bpp = channels
    for y in range(height):
        base = y * (stride + 1)
        ftype = raw[base]
        line = bytearray(raw[base + 1:base + 1 + stride])
        if ftype == 1:
            for i in range(bpp, stride):
                line[i] = (line[i] + line[i - bpp]) & 0xFF
        elif ftype == 2:
            for i in range(stride):
                line[i] = (line[i] + prev[i]) & 0xFF
        elif ftype == 3:
            for i in range(stride):
                left = line[i - bpp] if i >= bpp else 0
                line[i] = (line[i] + ((left + prev[i]) >> 1)) & 0xFF
        elif ftype == 4:
            for i in range(stride):
                left = line[i - bpp] if i >= bpp else 0
                upleft = prev[i - bpp] if i >= bpp else 0
                line[i] = (line[i] + _paeth(left, prev[i], upleft)) & 0xFF
        elif ftype != 0:
            raise PngError("bad filter type %d in row %d" % (ftype, y))
        out[y * stride:(y + 1) * stride] = line
        prev = line
    if channels == 4:
        return width, height, bytes(out)
    rgba = bytearray(width * height * 4)
    n = width * height
    if channels == 3:
        for i in range(n):
            rgba[i * 4:i * 4 + 3] = out[i * 3:i * 3 + 3]
            rgba[i * 4 + 3] = 255
    elif channels == 1:
        for i in range(n):
            g = out[i]
            rgba[i * 4:i * 4 + 4] = bytes((g, g, g, 255))
    else:  # grey + alpha
        for i in range(n):
            g = out[i * 2]
            rgba[i * 4:i * 4 + 4] = bytes((g, g, g, out[i * 2 + 1]))
    return width, height, bytes(rgba)


def read_png(path):
    with open(path, "rb") as f:
        return decode_png(f.read())
