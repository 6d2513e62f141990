#!/usr/bin/env python3
"""png_not_blank.py <shot.png> [--min-ink F] [--color #rrggbb ...]

Checks that a screenshot is not blank, using only the standard library (zlib): decodes an 8-bit
non-interlaced PNG (PNG spec, ISO/IEC 15948: IHDR, IDAT, filters 0-4 incl. Paeth), counts
pixels that are not white, and, for each --color, pixels within 40 of that colour per channel
(anti-aliasing and the fill opacities of the report shift colours; 40/255 still tells the Tableau
palette entries apart). Exit 0 when at least --min-ink of the pixels are non-white and every
colour is present on at least 200 pixels (a rendered line of a few hundred pixels); 1 otherwise.
"""
import struct
import sys
import zlib


def decode(path):
    data = open(path, 'rb').read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise ValueError('not a PNG file')
    pos, idat, ihdr = 8, [], None
    while pos < len(data):
        length, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b'IHDR':
            ihdr = struct.unpack('>IIBBBBB', body)
        elif kind == b'IDAT':
            idat.append(body)
        elif kind == b'IEND':
            break
        pos += 12 + length
    width, height, depth, ctype, _, _, interlace = ihdr
    channels = {0: 1, 2: 3, 4: 2, 6: 4}.get(ctype)
    if depth != 8 or channels is None or interlace:
        raise ValueError('unsupported PNG: depth %d colour type %d interlace %d'
                         % (depth, ctype, interlace))
    raw = zlib.decompress(b''.join(idat))
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        ftype = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if ftype == 1:
                line[i] = (line[i] + a) & 255
            elif ftype == 2:
                line[i] = (line[i] + b) & 255
            elif ftype == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif ftype == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + pred) & 255
        rows.append(line)
        prev = line
    return width, height, channels, rows


def main(argv):
    path, min_ink, colors = None, 0.01, []
    args = iter(argv[1:])
    for a in args:
        if a == '--min-ink':
            min_ink = float(next(args))
        elif a == '--color':
            h = next(args).lstrip('#')
            colors.append(tuple(int(h[i:i + 2], 16) for i in (0, 2, 4)))
        else:
            path = a
    width, height, ch, rows = decode(path)
    ink, hits = 0, [0] * len(colors)
    for line in rows:
        for x in range(width):
            px = line[x * ch:x * ch + ch]
            rgb = (px[0], px[0], px[0]) if ch < 3 else tuple(px[:3])
            if min(rgb) < 245:
                ink += 1
                for k, c in enumerate(colors):
                    if all(abs(rgb[j] - c[j]) <= 40 for j in range(3)):
                        hits[k] += 1
    frac = ink / float(width * height)
    print('%dx%d, %.2f %% non-white pixels' % (width, height, 100 * frac))
    ok = frac >= min_ink
    for c, n in zip(colors, hits):
        print('colour #%02x%02x%02x: %d pixels' % (c + (n,)))
        ok = ok and n >= 200
    print('OK' if ok else 'BLANK OR MISSING COLOURS')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main(sys.argv))
