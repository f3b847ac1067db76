#!/usr/bin/env python3
"""Writes GLUT's font data (font_data.h) as C++ from Debian's font packages.

Bitmap fonts: X11 PCF fonts of xfonts-base (misc-fixed 8x13 and 9x15: public domain) and
xfonts-75dpi (Adobe Times and Helvetica at 75 dpi; the copyright file of xfonts-75dpi grants
use, copying and distribution). These are the X fonts GLUT's bitmap fonts were taken from.

Stroke fonts: the Hershey fonts of hershey-fonts-data (Roman Simplex, rowmans.jhf), as GLUT's
stroke fonts are. Acknowledgements the Hershey font licence asks to be distributed with the data:
 - The Hershey Fonts were originally created by Dr. A. V. Hershey while working at the U. S.
   National Bureau of Standards.
 - The format of the Font data in this distribution was originally created by James Hurt,
   Cognition, Inc., 900 Technology Park Drive, Billerica, MA 01821.

usage: make_font_data.py OUT.cpp X11_FONT_DIR HERSHEY_DIR
"""
import gzip
import os
import struct
import sys

PCF_ACCELERATORS = 1 << 1
PCF_METRICS = 1 << 2
PCF_BITMAPS = 1 << 3
PCF_BDF_ENCODINGS = 1 << 5
PCF_BDF_ACCELERATORS = 1 << 8
PCF_COMPRESSED_METRICS = 0x100

BITMAP_FONTS = [  # (C++ name, GLUT name, file)
    ("kFixed8x13", "8x13", "misc/8x13-ISO8859-1.pcf.gz"),
    ("kFixed9x15", "9x15", "misc/9x15-ISO8859-1.pcf.gz"),
    ("kTimesRoman10", "Times Roman 10", "75dpi/timR10-ISO8859-1.pcf.gz"),
    ("kTimesRoman24", "Times Roman 24", "75dpi/timR24-ISO8859-1.pcf.gz"),
    ("kHelvetica10", "Helvetica 10", "75dpi/helvR10-ISO8859-1.pcf.gz"),
    ("kHelvetica12", "Helvetica 12", "75dpi/helvR12-ISO8859-1.pcf.gz"),
    ("kHelvetica18", "Helvetica 18", "75dpi/helvR18-ISO8859-1.pcf.gz"),
]


class Table:
    """One PCF table: its format word decides byte order, bit order and padding."""

    def __init__(self, data, offset):
        self.data = data
        self.pos = offset
        self.format = struct.unpack_from("<I", data, offset)[0]
        self.pos += 4
        self.big = bool(self.format & (1 << 2))

    def read(self, code):
        value = struct.unpack_from((">" if self.big else "<") + code, self.data, self.pos)
        self.pos += struct.calcsize(code)
        return value[0]


def read_pcf(path):
    data = gzip.open(path).read()
    if data[:4] != b"\x01fcp":
        raise SystemExit(f"{path}: not a PCF font")
    count = struct.unpack_from("<I", data, 4)[0]
    tables = {}
    for i in range(count):
        kind, _, _, offset = struct.unpack_from("<IIII", data, 8 + 16 * i)
        tables[kind] = offset

    t = Table(data, tables[PCF_METRICS])
    metrics = []
    if t.format & PCF_COMPRESSED_METRICS:
        for _ in range(t.read("H")):
            left, right, width, ascent, descent = (t.read("B") - 0x80 for _ in range(5))
            metrics.append((left, right, width, ascent, descent))
    else:
        for _ in range(t.read("I")):
            left, right, width, ascent, descent, _attributes = (t.read("h") for _ in range(6))
            metrics.append((left, right, width, ascent, descent))

    t = Table(data, tables[PCF_BITMAPS])
    glyph_count = t.read("I")
    offsets = [t.read("I") for _ in range(glyph_count)]
    sizes = [t.read("I") for _ in range(4)]
    pad = 1 << (t.format & 3)
    msb_bit_first = bool(t.format & (1 << 3))
    unit = 1 << ((t.format >> 4) & 3)
    bitmap_data = data[t.pos:t.pos + sizes[t.format & 3]]

    t = Table(data, tables[PCF_BDF_ENCODINGS])
    first_col, last_col, first_row, last_row, _default = (t.read("h") for _ in range(5))
    encoding = {}
    for row in range(first_row, last_row + 1):
        for col in range(first_col, last_col + 1):
            index = t.read("H")
            if index != 0xFFFF:
                encoding[(row << 8) | col] = index

    t = Table(data, tables.get(PCF_BDF_ACCELERATORS, tables.get(PCF_ACCELERATORS)))
    t.pos += 8  # flags
    font_ascent, font_descent = t.read("i"), t.read("i")

    def pixel(glyph, x, y):
        left, right, _, ascent, descent = metrics[glyph]
        stride = ((right - left) + pad * 8 - 1) // (pad * 8) * pad
        byte_index = offsets[glyph] + y * stride + x // 8
        if not t.big and unit > 1:  # bytes within a scan unit are stored little end first
            base = byte_index - byte_index % unit
            byte_index = base + (unit - 1 - (byte_index - base))
        byte = bitmap_data[byte_index]
        bit = x % 8
        return bool(byte & (0x80 >> bit) if msb_bit_first else byte & (1 << bit))

    glyphs = {}
    for code in range(256):
        if code not in encoding:
            continue
        g = encoding[code]
        left, right, width, ascent, descent = metrics[g]
        w, h = right - left, ascent + descent
        rows = []
        for y in reversed(range(h)):  # bottom row first, as glBitmap takes them
            row = bytearray((w + 7) // 8)
            for x in range(w):
                if pixel(g, x, y):
                    row[x // 8] |= 0x80 >> (x % 8)
            rows.append(bytes(row))
        glyphs[code] = (w, h, -left, descent, width, b"".join(rows))
    return font_ascent, font_descent, glyphs


def write_bitmap_font(out, cname, glut_name, path):
    ascent, descent, glyphs = read_pcf(path)
    bits = bytearray()
    entries = []
    for code in range(256):
        if code in glyphs:
            w, h, xorig, yorig, advance, data = glyphs[code]
            entries.append(f"{{{w}, {h}, {xorig}, {yorig}, {advance}, {len(bits)}}}")
            bits += data
        else:
            entries.append("{0, 0, 0, 0, 0, 0}")
    short = cname[1:]
    out.write(f"// {glut_name}: {os.path.basename(path)}\n")
    out.write(f"const std::uint8_t k{short}Bits[] = {{\n")
    for i in range(0, len(bits), 24):
        out.write("    " + ", ".join(str(b) for b in bits[i:i + 24]) + ",\n")
    out.write("    0};\n")
    out.write(f"const BitmapGlyph k{short}Glyphs[256] = {{\n")
    for i in range(0, 256, 4):
        out.write("    " + ", ".join(entries[i:i + 4]) + ",\n")
    out.write("};\n")
    # The line height: the font's ascent and descent plus one row between lines.
    out.write(f'const BitmapFont {cname}{{"{glut_name}", {ascent + descent + 1}, k{short}Glyphs, k{short}Bits}};\n\n')


HERSHEY_SCALE = 100.0 / 21.0  # capitals are 21 Hershey units high; GLUT's are 100
HERSHEY_BASELINE = 9          # Hershey y grows downwards; capitals sit on y = 9
MONO_ADVANCE = 22             # Hershey units of every Mono Roman character


def read_hershey(path):
    glyphs = []
    for line in open(path):
        line = line.rstrip("\n")
        if not line.strip():
            continue
        pairs = int(line[5:8])
        body = line[8:8 + 2 * pairs]
        left, right = ord(body[0]) - ord("R"), ord(body[1]) - ord("R")
        strips, strip = [], []
        for i in range(2, len(body), 2):
            if body[i:i + 2] == " R":
                strips.append(strip)
                strip = []
            else:
                strip.append((ord(body[i]) - ord("R"), ord(body[i + 1]) - ord("R")))
        strips.append(strip)
        glyphs.append((left, right, [s for s in strips if s]))
    return glyphs


def write_stroke_font(out, cname, glut_name, glyphs, mono):
    points, strips, entries = [], [], ["{0.0f, 0, 0}"] * 256
    for i, (left, right, glyph_strips) in enumerate(glyphs[:95]):  # ASCII 32..126
        width = right - left
        shift = (MONO_ADVANCE - width) / 2 if mono else 0
        advance = MONO_ADVANCE if mono else width
        first = len(strips)
        for strip in glyph_strips:
            strips.append(f"{{{len(points) // 2}, {len(strip)}}}")
            for x, y in strip:
                points += [(x - left + shift) * HERSHEY_SCALE, (HERSHEY_BASELINE - y) * HERSHEY_SCALE]
        entries[32 + i] = f"{{{advance * HERSHEY_SCALE:.4f}f, {first}, {len(strips) - first}}}"
    short = cname[1:]
    out.write(f"// {glut_name}: Hershey Roman Simplex{' centred in equal cells' if mono else ''}\n")
    out.write(f"const float k{short}Points[] = {{\n")
    for i in range(0, len(points), 8):
        out.write("    " + ", ".join(f"{p:.4f}f" for p in points[i:i + 8]) + ",\n")
    out.write("};\n")
    out.write(f"const StrokeStrip k{short}Strips[] = {{\n")
    for i in range(0, len(strips), 8):
        out.write("    " + ", ".join(strips[i:i + 8]) + ",\n")
    out.write("};\n")
    out.write(f"const StrokeGlyph k{short}Glyphs[256] = {{\n")
    for i in range(0, 256, 4):
        out.write("    " + ", ".join(entries[i:i + 4]) + ",\n")
    out.write("};\n")
    height = 32 * HERSHEY_SCALE  # the Hershey em: 16 units either side of the centre line
    out.write(f'const StrokeFont {cname}{{"{glut_name}", {height:.4f}f, k{short}Glyphs, k{short}Strips, k{short}Points}};\n\n')


def main():
    out_path, x11_dir, hershey_dir = sys.argv[1:4]
    with open(out_path + ".tmp", "w") as out:
        out.write("// Generated by make_font_data.py from Debian's font packages; see there for the\n")
        out.write("// sources and the acknowledgements their licences ask for. Do not edit.\n")
        out.write('#include "font_data.h"\n\nnamespace glut::fonts {\n\n')
        for cname, glut_name, path in BITMAP_FONTS:
            write_bitmap_font(out, cname, glut_name, os.path.join(x11_dir, path))
        roman = read_hershey(os.path.join(hershey_dir, "rowmans.jhf"))
        write_stroke_font(out, "kRoman", "Roman", roman, False)
        write_stroke_font(out, "kMonoRoman", "Mono Roman", roman, True)
        out.write("}  // namespace glut::fonts\n")
    os.replace(out_path + ".tmp", out_path)


if __name__ == "__main__":
    main()
