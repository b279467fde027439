#!/usr/bin/env python3
"""Compare two pictures of the same size by 8x8 block means.

The picture is split into 8x8 blocks (partial blocks at the right and bottom edges when
the size is not a multiple of 8); for each block and each of R, G, B the mean byte value
is taken. The pictures MATCH when no block mean differs by more than 12/255 (12 in byte
units). Block means forgive pixel-level noise (rounding, dithering, the last bits of
transcendental functions) but catch any visible region that differs.

Importable:  compare_pictures.compare(a, b) / compare_files(path_a, path_b) -> Comparison
CLI:         python3 tools/browser/compare_pictures.py A.png B.png [--block 8] [--threshold 12]
             prints MATCH or MISMATCH and the worst block difference; exit 0 on MATCH, 1 on
             MISMATCH, 2 on unreadable input or a size difference.
Reads 8-bit non-interlaced RGB/RGBA (and grey) PNGs (tools/browser/pngio.py).
"""

import argparse
import os
import sys
from collections import namedtuple

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pngio import PngError, decode_png, read_png  # noqa: E402,F401  (re-exported)

DEFAULT_BLOCK = 8
DEFAULT_THRESHOLD = 12.0  # byte units: 12/255

Comparison = namedtuple("Comparison", [
    "match",        # bool: worst <= threshold
    "worst",        # largest |mean difference| of any block and channel, in byte units
    "worst_block",  # (x, y) pixel position of the worst block's top-left corner
    "worst_channel",  # "R", "G" or "B"
    "blocks_over",  # how many blocks differ by more than the threshold
    "blocks",       # total number of blocks
    "mean_abs",     # mean |difference| over all pixels and RGB channels, byte units
])


def block_means(width, height, rgba, block=DEFAULT_BLOCK):
    """{(bx, by): (meanR, meanG, meanB)} for each block (bx, by in pixels)."""
    means = {}
    for by in range(0, height, block):
        for bx in range(0, width, block):
            sums = [0, 0, 0]
            count = 0
            for y in range(by, min(by + block, height)):
                row = (y * width) * 4
                for x in range(bx, min(bx + block, width)):
                    i = row + x * 4
                    sums[0] += rgba[i]
                    sums[1] += rgba[i + 1]
                    sums[2] += rgba[i + 2]
                    count += 1
            means[(bx, by)] = tuple(s / count for s in sums)
    return means


def compare(a, b, block=DEFAULT_BLOCK, threshold=DEFAULT_THRESHOLD):
    """a, b: (width, height, rgba bytes). Raises ValueError when the sizes differ."""
    wa, ha, pa = a
    wb, hb, pb = b
    if (wa, ha) != (wb, hb):
        raise ValueError("sizes differ: %dx%d vs %dx%d" % (wa, ha, wb, hb))
    ma = block_means(wa, ha, pa, block)
    mb = block_means(wb, hb, pb, block)
    worst = -1.0
    worst_block = (0, 0)
    worst_channel = "R"
    over = 0
    for key in ma:
        diffs = [abs(x - y) for x, y in zip(ma[key], mb[key])]
        d = max(diffs)
        if d > threshold:
            over += 1
        if d > worst:
            worst = d
            worst_block = key
            worst_channel = "RGB"[diffs.index(d)]
    total = 0
    for i in range(0, len(pa), 4):
        total += abs(pa[i] - pb[i]) + abs(pa[i + 1] - pb[i + 1]) + abs(pa[i + 2] - pb[i + 2])
    mean_abs = total / (3.0 * wa * ha) if wa * ha else 0.0
    return Comparison(worst <= threshold, max(worst, 0.0), worst_block, worst_channel, over,
                      len(ma), mean_abs)


def compare_files(path_a, path_b, block=DEFAULT_BLOCK, threshold=DEFAULT_THRESHOLD):
    return compare(read_png(path_a), read_png(path_b), block, threshold)


def describe(c, threshold=DEFAULT_THRESHOLD):
    return ("%s: worst block difference %.1f/255 (%s, block at x=%d y=%d from the top-left), "
            "%d of %d blocks over %g, mean pixel difference %.2f/255" %
            ("MATCH" if c.match else "MISMATCH", c.worst, c.worst_channel, c.worst_block[0],
             c.worst_block[1], c.blocks_over, c.blocks, threshold, c.mean_abs))


def main(argv=None):
    ap = argparse.ArgumentParser(
        description="Compare two same-size PNGs by 8x8 block RGB means; MATCH when no block mean "
                    "differs by more than 12/255.")
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--block", type=int, default=DEFAULT_BLOCK, help="block size (default 8)")
    ap.add_argument("--threshold", type=float, default=DEFAULT_THRESHOLD,
                    help="largest allowed block mean difference in byte units (default 12)")
    args = ap.parse_args(argv)
    try:
        c = compare_files(args.a, args.b, args.block, args.threshold)
    except (OSError, PngError, ValueError) as e:
        print("error: %s" % e, file=sys.stderr)
        return 2
    print(describe(c, args.threshold))
    return 0 if c.match else 1


if __name__ == "__main__":
    sys.exit(main())
