#!/usr/bin/env python3
"""tools/check_figure_keys.py WITH.png WITHOUT.png [NAME]: does the key (legend) of a figure cover
anything? WITH is the figure as drawn, WITHOUT the same figure drawn with its key off. The pixels
that differ are the key's (its box, samples and text); in WITHOUT, every pixel of their bounding
box must be background (white): otherwise the key hides data, a grid line, a label or the title.
Exit 1 with the covered area and a count of the pixels it hides; 0 when the key is clear (or there
is no key). Reads 8-bit RGB(A) PNG (gnuplot's pngcairo) with the standard library only."""
import struct
import sys
import zlib

# A pixel with every channel at least this bright counts as background (anti-aliasing of text in
# the key itself stays inside the key's own pixels).
WHITE = 245


def read_png(path):
    with open(path, 'rb') as f:
        data = f.read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise ValueError(path + ': not a PNG file')
    pos, idat = 8, b''
    width = height = depth = ctype = None
    while pos < len(data):
        length, kind = struct.unpack('>I4s', data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        if kind == b'IHDR':
            width, height, depth, ctype, _, _, interlace = struct.unpack('>IIBBBBB', chunk)
            if depth != 8 or ctype not in (2, 6) or interlace:
                raise ValueError('%s: only 8-bit RGB or RGBA non-interlaced PNG is read' % path)
        elif kind == b'IDAT':
            idat += chunk
        pos += 12 + length
    bpp = 3 if ctype == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * bpp
    rows, prev, i = [], bytearray(stride), 0
    for _ in range(height):
        ftype = raw[i]
        line = bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if ftype == 1:
                line[x] = (line[x] + a) & 255
            elif ftype == 2:
                line[x] = (line[x] + b) & 255
            elif ftype == 3:
                line[x] = (line[x] + ((a + b) >> 1)) & 255
            elif ftype == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[x] = (line[x] + pred) & 255
        rows.append(bytes(line))
        prev = line
    return width, height, bpp, rows


def main():
    with_key, without_key = sys.argv[1], sys.argv[2]
    name = sys.argv[3] if len(sys.argv) > 3 else with_key
    w1, h1, b1, a = read_png(with_key)
    w2, h2, b2, b = read_png(without_key)
    if (w1, h1) != (w2, h2):
        print('%s: the two drawings differ in size (%dx%d, %dx%d)' % (name, w1, h1, w2, h2))
        sys.exit(1)
    x0, y0, x1, y1 = w1, h1, -1, -1
    for y in range(h1):
        ra, rb = a[y], b[y]
        if ra == rb:
            continue
        for x in range(w1):
            if ra[x * b1:x * b1 + 3] != rb[x * b2:x * b2 + 3]:
                x0, y0, x1, y1 = min(x0, x), min(y0, y), max(x1, x), max(y1, y)
    if x1 < 0:
        print('%s: no key' % name)
        return
    hidden = 0
    for y in range(y0, y1 + 1):
        row = b[y]
        for x in range(x0, x1 + 1):
            if min(row[x * b2:x * b2 + 3]) < WHITE:
                hidden += 1
    area = (x1 - x0 + 1) * (y1 - y0 + 1)
    if hidden:
        print('%s: the key (pixels %d-%d across, %d-%d down) covers %d drawn pixels of %d' %
              (name, x0, x1, y0, y1, hidden, area))
        sys.exit(1)
    print('%s: the key (pixels %d-%d across, %d-%d down) covers nothing' % (name, x0, x1, y0, y1))


main()
