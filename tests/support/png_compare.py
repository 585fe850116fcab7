#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Compares two 8-bit RGB(A) PNGs of one size, for tests that render twice:
#   python3 png_compare.py halves with_pass.png plain.png
#     a pass that draws over the left half: exits 0 when the left halves differ (mean absolute
#     difference of the color channels at least --differs) and the right halves agree (no
#     channel more than --agrees apart), else 1, saying which;
#   python3 png_compare.py same a.png b.png
#     exits 0 when no channel of any pixel is more than --agrees apart, else 1.
import argparse
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path}: not a PNG")
    offset, idat, header = 8, b"", None
    while offset < len(data):
        length, kind = struct.unpack(">I4s", data[offset:offset + 8])
        body = data[offset + 8:offset + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        offset += 12 + length
    width, height, depth, color_type, _, _, interlace = header
    if depth != 8 or color_type not in (2, 6) or interlace:
        sys.exit(f"{path}: only 8-bit RGB or RGBA, not interlaced")
    channels = 4 if color_type == 6 else 3
    stride = width * channels
    raw = zlib.decompress(idat)
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up = previous[i]
            upper_left = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - upper_left
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - upper_left)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else upper_left)) & 255
        rows.append(line)
        previous = line
    return width, height, channels, rows


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("mode", choices=["halves", "same"])
    parser.add_argument("drawn")
    parser.add_argument("plain")
    parser.add_argument("--differs", type=float, default=2.0, help="least mean difference on the left")
    parser.add_argument("--agrees", type=int, default=1, help="most difference of any channel on the right")
    args = parser.parse_args()
    w, h, c, a = read_png(args.drawn)
    w2, h2, c2, b = read_png(args.plain)
    if (w, h, c) != (w2, h2, c2):
        sys.exit(f"sizes differ: {w}x{h}x{c} against {w2}x{h2}x{c2}")
    half = 0 if args.mode == "same" else w // 2
    left_sum, left_count, right_most = 0, 0, 0
    for y in range(h):
        for x in range(w):
            for k in range(3):
                d = abs(a[y][x * c + k] - b[y][x * c + k])
                if x < half:
                    left_sum += d
                    left_count += 1
                else:
                    right_most = max(right_most, d)
    if args.mode == "same":
        print(f"largest difference {right_most}")
        if right_most > args.agrees:
            print("the pictures differ")
            return 1
        return 0
    left_mean = left_sum / left_count
    print(f"left half: mean difference {left_mean:.2f}; right half: largest difference {right_most}")
    if left_mean < args.differs:
        print("the left halves do not differ enough: the pass drew nothing")
        return 1
    if right_most > args.agrees:
        print("the right halves differ: something drew outside the pass's half")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
