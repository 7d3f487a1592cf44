#!/usr/bin/env python3
"""Whether a rendered picture shows something: the image half of check-blender.sh.

A picture fails when it is blank (near uniform: the standard deviation of its pixels'
luma below --min-std, on a scale of 0 to 1) or when one flat colour that is not dark
(within about 3 of 255 per channel, Blender's dithering) covers more than --max-flat
of it: a frame that is mostly the empty world behind the model, e.g. the building
seen from outside (a path-traced room is noisy and shaded, the world behind it one
colour). Exit 0 when it passes, 1 when it fails, 2 when the
file cannot be read.

    python3 scripts/check_image.py PICTURE.png [--min-std 0.02] [--max-flat 0.5]

Needs nothing but Python's standard library (its own PNG reader: 8- and 16-bit grey,
grey + alpha, RGB, RGBA and palette images, not interlaced), so that it runs with the
system's python3 and inside Blender alike (blender_render.py imports it).
"""
import argparse
import struct
import sys
import zlib
from collections import Counter

MIN_STD = 0.02
MAX_FLAT = 0.5
FLAT_BIN = 2
FLAT_MIN_LUMA = 0.1


class PngError(Exception):
    pass


def read_png(path):
    """(width, height, rows): rows of (r, g, b) tuples in 0..1, top row first."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise PngError(f"{path}: not a PNG file")
    pos, idat, palette, header = 8, [], None, None
    while pos + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        if len(chunk) != length:
            raise PngError(f"{path}: truncated {kind.decode('latin-1')} chunk")
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", chunk)
        elif kind == b"PLTE":
            palette = [tuple(chunk[i:i + 3]) for i in range(0, len(chunk) - 2, 3)]
        elif kind == b"IDAT":
            idat.append(chunk)
        elif kind == b"IEND":
            break
    if header is None:
        raise PngError(f"{path}: no IHDR chunk")
    width, height, depth, color, _, _, interlace = header
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}.get(color)
    if channels is None or depth not in (8, 16) or (color == 3 and depth != 8) or interlace:
        raise PngError(f"{path}: unsupported PNG (bit depth {depth}, colour type {color}, interlace {interlace})")
    if color == 3 and not palette:
        raise PngError(f"{path}: palette image without PLTE")
    try:
        raw = zlib.decompress(b"".join(idat))
    except zlib.error as e:
        raise PngError(f"{path}: {e}")
    bpp = channels * depth // 8  # bytes per pixel
    stride = width * bpp
    if len(raw) < height * (stride + 1):
        raise PngError(f"{path}: image data cut short")
    rows, previous = [], bytearray(stride)
    scale = 255.0 if depth == 8 else 65535.0
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        if kind == 1:
            for i in range(bpp, stride):
                line[i] = (line[i] + line[i - bpp]) & 255
        elif kind == 2:
            for i in range(stride):
                line[i] = (line[i] + previous[i]) & 255
        elif kind == 3:
            for i in range(stride):
                left = line[i - bpp] if i >= bpp else 0
                line[i] = (line[i] + ((left + previous[i]) >> 1)) & 255
        elif kind == 4:
            for i in range(stride):
                a = line[i - bpp] if i >= bpp else 0
                b = previous[i]
                c = previous[i - bpp] if i >= bpp else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        elif kind != 0:
            raise PngError(f"{path}: bad filter type {kind} in row {y}")
        previous = line
        if depth == 16:
            values = struct.unpack(f">{width * channels}H", bytes(line))
        else:
            values = line
        row = []
        for x in range(width):
            v = values[x * channels:(x + 1) * channels]
            if color == 3:
                r, g, b = palette[v[0]] if v[0] < len(palette) else (0, 0, 0)
                row.append((r / 255.0, g / 255.0, b / 255.0))
            elif channels <= 2:  # grey (+ alpha)
                row.append((v[0] / scale,) * 3)
            else:
                row.append((v[0] / scale, v[1] / scale, v[2] / scale))
        rows.append(row)
    return width, height, rows


def image_stats(rows):
    """Mean and standard deviation of the pixels' luma, and the largest share of pixels
    of one flat colour that is not dark: colours binned by FLAT_BIN levels (of 255) per
    channel, each bin counted with its 26 neighbours (about +-3 levels: a flat world stays
    flat under Blender's dithering, a path-traced surface does not), over the bins of
    luma at least FLAT_MIN_LUMA (dark is no light, not the world: a dim room's noise
    sits near black; a black frame fails the standard deviation)."""
    n, total, squares = 0, 0.0, 0.0
    bins = Counter()
    for row in rows:
        for r, g, b in row:
            luma = 0.2126 * r + 0.7152 * g + 0.0722 * b
            total += luma
            squares += luma * luma
            bins[(round(r * 255) // FLAT_BIN, round(g * 255) // FLAT_BIN, round(b * 255) // FLAT_BIN)] += 1
            n += 1
    if n == 0:
        return 0.0, 0.0, 1.0
    mean = total / n
    std = max(squares / n - mean * mean, 0.0) ** 0.5
    flat = 0
    for (r, g, b) in bins:
        if (0.2126 * r + 0.7152 * g + 0.0722 * b) * FLAT_BIN < FLAT_MIN_LUMA * 255:
            continue
        flat = max(flat, sum(bins.get((r + i, g + j, b + k), 0) for i in (-1, 0, 1) for j in (-1, 0, 1) for k in (-1, 0, 1)))
    return mean, std, flat / n


def check(path, min_std=MIN_STD, max_flat=MAX_FLAT):
    """(ok, message) for the picture at `path`; raises PngError when it cannot be read."""
    width, height, rows = read_png(path)
    mean, std, flat = image_stats(rows)
    what = f"{path}: {width} x {height}, mean luma {mean:.3f}, std {std:.3f}, one flat colour {100 * flat:.0f}%"
    if std < min_std:
        return False, f"{what}: blank (std below {min_std})"
    if flat > max_flat:
        return False, f"{what}: mostly one flat colour (over {100 * max_flat:.0f}%): the background, not the room"
    return True, what


def main(argv):
    parser = argparse.ArgumentParser(description="Fail on a blank picture or one that is mostly background.")
    parser.add_argument("png")
    parser.add_argument("--min-std", type=float, default=MIN_STD, help="least standard deviation of luma (0..1)")
    parser.add_argument("--max-flat", type=float, default=MAX_FLAT, help="largest share of one exact colour")
    args = parser.parse_args(argv)
    try:
        ok, message = check(args.png, args.min_std, args.max_flat)
    except (OSError, PngError) as e:
        print(f"check-image: {e}")
        return 2
    print(f"check-image: {message}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
