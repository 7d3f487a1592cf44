#!/usr/bin/env python3
"""check-blender.sh's picture check (scripts/check-blender.sh --image, check_image.py)
on pictures made here: a blank one and a uniform grey one fail, one that is mostly
flat background (exact or dithered as Blender writes it) with the model small fails, a shaded and noisy one (what Cycles
gives for a room seen from inside) passes, in 8- and 16-bit RGB, RGBA, grey and
palette PNGs written with every PNG row filter; a file that is no PNG is an error.

    python3 tests/scripts/check_image_test.py scripts/check-blender.sh
"""
import os
import random
import struct
import subprocess
import sys
import tempfile
import zlib


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else b if pb <= pc else c


def write_png(path, width, height, pixel, color=2, depth=8, palette=None):
    """pixel(x, y) -> a tuple of the colour type's channels (0..255, or 0..65535 at 16 bits)."""
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[color]
    bpp = channels * depth // 8
    raw, previous = bytearray(), bytearray(width * bpp)
    for y in range(height):
        line = bytearray()
        for x in range(width):
            for v in pixel(x, y):
                line += struct.pack(">H", v) if depth == 16 else bytes([v])
        kind = y % 5  # every filter type in turn
        out = bytearray()
        for i, v in enumerate(line):
            a = line[i - bpp] if i >= bpp else 0
            b = previous[i]
            c = previous[i - bpp] if i >= bpp else 0
            predicted = [0, a, b, (a + b) >> 1, paeth(a, b, c)][kind]
            out.append((v - predicted) & 255)
        raw += bytes([kind]) + out
        previous = line

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, depth, color, 0, 0, 0))
    if palette:
        png += chunk(b"PLTE", b"".join(bytes(p) for p in palette))
    png += chunk(b"IDAT", zlib.compress(bytes(raw))) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def room(x, y, rng):
    """A room seen from inside: floor darker than walls, a window, path-tracing noise."""
    base = 0.25 + 0.4 * (y < 60) + 0.3 * (40 < x < 70 and 15 < y < 45)
    v = max(0.0, min(1.0, base * (1 - 0.3 * x / 160) + rng.gauss(0, 0.04)))
    return v


def main(check_blender):
    rng = random.Random(1)
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        def case(name, expect, **png):
            path = os.path.join(tmp, name + ".png")
            if "bytes" in png:
                with open(path, "wb") as f:
                    f.write(png["bytes"])
            else:
                write_png(path, 160, 120, **png)
            r = subprocess.run(["bash", check_blender, "--image", path], capture_output=True, text=True)
            verdict = "ok" if r.returncode == expect else "WRONG"
            print(f"{verdict}: {name}: exit {r.returncode} (expected {expect}): {r.stdout.strip()} {r.stderr.strip()}")
            if r.returncode != expect:
                failures.append(name)

        case("blank-black", 1, pixel=lambda x, y: (0, 0, 0))
        case("blank-white-rgba", 1, color=6, pixel=lambda x, y: (255, 255, 255, 255))
        case("uniform-grey-16bit", 1, depth=16, pixel=lambda x, y: (30000, 30000, 30000))
        case("faint-noise", 1, pixel=lambda x, y: (128 + (x + y) % 2,) * 3)
        # The building from far outside: the world's flat colour with a small grey block.
        case("outside-speck", 1,
             pixel=lambda x, y: (90, 90, 90) if 70 < x < 90 and 50 < y < 64 else (200, 215, 235))
        # The same as Blender writes it: the world dithered by a level or two.
        dither = random.Random(2)
        case("outside-dithered", 1,
             pixel=lambda x, y: (90, 90, 90) if 40 < x < 120 and 40 < y < 70
             else tuple(v + dither.choice((-1, 0, 0, 1)) for v in (183, 197, 215)))
        # The room from inside, as Cycles renders it.
        shade = {}
        for y in range(120):
            for x in range(160):
                shade[x, y] = room(x, y, rng)
        case("room-rgb", 0, pixel=lambda x, y: tuple(int(255 * shade[x, y] * k) for k in (1.0, 0.95, 0.9)))
        case("room-rgba", 0, color=6, pixel=lambda x, y: (int(255 * shade[x, y]),) * 3 + (255,))
        case("room-grey-16bit", 0, color=0, depth=16, pixel=lambda x, y: (int(65535 * shade[x, y]),))
        case("room-grey-alpha", 0, color=4, pixel=lambda x, y: (int(255 * shade[x, y]), 255))
        case("room-palette", 0, color=3, palette=[(k, k, k) for k in range(256)],
             pixel=lambda x, y: (int(255 * shade[x, y]),))
        case("not-a-png", 2, bytes=b"GIF89a no picture")
    if failures:
        print(f"check_image_test: {len(failures)} wrong: {', '.join(failures)}")
        return 1
    print("check_image_test: every picture judged as expected")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
