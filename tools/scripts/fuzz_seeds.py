#!/usr/bin/env python3
"""Writes the fuzz targets' seed inputs, tests/fuzz/seeds/TARGET/.

usage: tools/scripts/fuzz_seeds.py [DEMO.ngc]

pipeline: the project's own programs (tests/gcode/paths, tests/gcode/bad
run together, tests/run, tests/fuzz/programs, and excerpts of the demo program that `dexmill
run` writes to out/demo.ngc, when DEMO.ngc is given), each behind a header
(tests/fuzz/fuzz_pipeline.cpp's PipelineHeader) whose grid covers the
program's XY extent; the other header bits vary from seed to seed so that
height types, cut modes, views, tool tables, design and backplot all have
seeds. A seed is the program's first 7 KB (the target's -max_len is 8192).
tool_table, stl, pgm: small valid files of each kind (ASCII and binary STL,
P2 and P5 PGM at 8 and 16 bits). The output is the same on every run.
"""
import math
import os
import re
import struct
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..'))
SEEDS = os.path.join(ROOT, 'tests', 'fuzz', 'seeds')
MAX_PROGRAM = 7000

TOOLS = ['flat:3', 'ball:6', 'bull:10:1.5,len=20', 'vbit:5:118', 'flat:6', 'ball:2.5', 'vbit:6:90,len=12', 'bull:4:1']
TABLE = ('T1 P1 D6 Z0 ;flat end mill 6 mm\n'
         'T2 P2 D6 Z+1.5 ;ball end mill 6 mm\n'
         'T3 P3 D6 Z0 ;spot drill vbit:6:90\n'
         'T4 P4 D10 Z-2 ;bull:10:1.5,len=25\n'
         '; a comment line\n'
         'T5 P5 D0.125 Z1 ;engraver\n')
# One pitch code a mm (1 + b % 32) * unit[b // 32], units as the target's.
UNITS_NM = [1000, 10000, 100000, 1000000, 1, 10, 100, 10000000]


def pitch_code(pitch_nm):
    """The smallest pitch code whose pitch is at least pitch_nm (um to mm units)."""
    best = None
    for b in range(256):
        p = (1 + (b & 31)) * UNITS_NM[b >> 5]
        if p >= pitch_nm and (best is None or p < best[1]):
            best = (b, p)
    return best


def extent_mm(text):
    """The program's X and Y range in mm, roughly (words as written, G20 scaled)."""
    scale = 25.4 if re.search(r'\bG20\b', text, re.I) else 1.0
    xs = [float(v) * scale for v in re.findall(r'X\s*(-?\d+\.?\d*)', text, re.I) if v not in ('-', '.')]
    ys = [float(v) * scale for v in re.findall(r'Y\s*(-?\d+\.?\d*)', text, re.I) if v not in ('-', '.')]
    # Words far out (the bad programs' out-of-range tests) do not set the grid.
    xs = [v for v in xs if abs(v) < 2000]
    ys = [v for v in ys if abs(v) < 2000]
    return min(xs + [0.0]), max(xs + [0.0]), min(ys + [0.0]), max(ys + [0.0])


def header(k, text, nx=48, ny=40):
    """The 12 header bytes of seed number k for program text."""
    x0, x1, y0, y1 = extent_mm(text)
    margin = 8.0
    span = max(x1 - x0, y1 - y0) + 2 * margin
    b3, pitch = pitch_code(int(math.ceil(span * 1e6 / (min(nx, ny) - 1))))
    # Origin: x0_nm = -(nx-1) p (b % 16) / 16; the largest fraction that still
    # reaches the program's lower end minus the margin.
    def frac(lo, n):
        want = -(lo - margin) * 1e6  # how far below 0 the grid must start
        f = int(math.ceil(want * 16 / ((n - 1) * pitch))) if want > 0 else 0
        return max(0, min(15, f))
    b4 = frac(x0, nx) | frac(y0, ny) << 4
    height = [0, 1, 2, 0][k % 4]          # 16, 8, 32, 16 bits
    flags = (k // 4) % 2                  # sweep, stamp
    flags |= height << 2
    flags |= 0x10 if k % 3 == 0 else 0    # tool table
    flags |= 0x20 if k % 5 in (1, 3) else 0  # design
    flags |= 0x40 if k % 2 == 1 else 0    # backplot
    flags |= 0x80 if k % 7 == 2 else 0    # RGB565
    if re.search(r'\bG20\b', text, re.I) and not re.search(r'\bG21\b', text, re.I):
        flags |= 0x02
    b5 = 20 | (k % 3) << 5                # 21 mm deep, headroom 0..2
    b6 = (k % 4) | (k % 6 == 5) << 2 | (k % 8 == 3) << 3 | ((k // 2) % 4) << 4
    b7 = (k % 5) | ((k // 3) % 4) << 5 | (k % 9 == 4) << 7
    b8, b9 = (0, 0) if k % 4 else (40 + 3 * k, 20)
    b10, b11 = 0x9c, 0x5f
    return bytes([flags, nx - 4, ny - 4, b3, b4, b5, b6, b7, b8 & 255, b9, b10, b11])


def pipeline_input(k, program, tool=None):
    program = program[:MAX_PROGRAM]
    cut = program.rfind('\n')
    if len(program) == MAX_PROGRAM and cut > 0:
        program = program[:cut + 1]
    h = header(k, program)
    text = (tool or TOOLS[k % len(TOOLS)]) + '\n'
    if h[0] & 0x10:
        text += TABLE + '\n'
    return h + (text + program).encode('latin-1')


def read(path):
    with open(path, 'rb') as f:
        return f.read().decode('latin-1')


def write(target, name, data):
    d = os.path.join(SEEDS, target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), 'wb') as f:
        f.write(data)


def demo_excerpts(demo):
    """The demo's start (units, first tool) with windows of its sections."""
    lines = demo.split('\n')
    head = '\n'.join(lines[:8]) + '\n'
    out = []
    starts = [i for i, l in enumerate(lines) if l.startswith('(')]
    for a in starts[2:]:
        body = '\n'.join(lines[a:a + 400])
        out.append(head + body[:MAX_PROGRAM - len(head) - 200] + '\nM2\n')
    # the middle of the finishing pass, in its own tool
    t2 = next(i for i, l in enumerate(lines) if l.startswith('(T2'))
    mid = (t2 + len(lines)) // 2
    out.append(head + '\n'.join(lines[t2:t2 + 4]) + '\n' + '\n'.join(lines[mid:mid + 300])[:MAX_PROGRAM - 600] + '\nM2\n')
    return out


def pipeline_seeds(demo_path):
    progs = []
    for sub in ('tests/gcode/paths', 'tests/run', 'tests/fuzz/programs'):
        for name in sorted(os.listdir(os.path.join(ROOT, sub))):
            if name.endswith('.ngc'):
                progs.append((name[:-4], read(os.path.join(ROOT, sub, name))))
    # The bad programs are a few lines each: run together, without the
    # program ends that would stop the rest.
    bad = sorted(os.listdir(os.path.join(ROOT, 'tests/gcode/bad')))
    for part in range(3):
        text = ''
        for name in bad[part::3]:
            body = read(os.path.join(ROOT, 'tests/gcode/bad', name))
            body = re.sub(r'(?im)^\s*(%|M0?2|M30)\s*$', '', body)
            text += '(%s)\n%s\n' % (name, body)
        progs.append(('bad_%d' % part, text + 'M2\n'))
    if demo_path:
        for i, text in enumerate(demo_excerpts(read(demo_path))):
            progs.append(('demo_%d' % i, text))
    for k, (name, text) in enumerate(progs):
        write('pipeline', '%02d_%s.bin' % (k, name), pipeline_input(k, text))


def tool_table_seeds():
    write('tool_table', 'demo.tbl', b'\x00' + TABLE.encode())
    write('tool_table', 'run_tools.tbl', b'\x00' + read(os.path.join(ROOT, 'tests/run/tools.tbl')).encode())
    write('tool_table', 'inch.tbl', b'\x01T1 P1 D0.25 Z+1.0 ;flat 1/4\r\nT2 P2 D.125 Z+1.25 I0 J0 Q0 ;ball\r\n'
          b'T7 P9 X0 Y0 A0 B0 C0 U0 V0 W0 D0.5 ;bull:0.5:0.05,len=1\r\n')
    write('tool_table', 'shapes.tbl', b'\x00T1 D3 ;flat\nt2 d6 ;Ball nose\nT3 D5 Z40 ;spot drill vbit:5:118\n'
          b'T4 D4 ;v-bit without a spec\nT5 D10 ;bull:99:2,len=20 (its D is the table\'s)\n')


def stl_ascii(tris, name='part'):
    s = 'solid %s\n' % name
    for t in tris:
        s += '  facet normal 0 0 1\n    outer loop\n'
        for v in t:
            s += '      vertex %s %s %s\n' % tuple(repr(float(c)) for c in v)
        s += '    endloop\n  endfacet\n'
    return (s + 'endsolid %s\n' % name).encode()


def stl_binary(tris):
    b = b'solid binary header that says solid'.ljust(80, b' ') + struct.pack('<I', len(tris))
    for t in tris:
        b += struct.pack('<3f', 0, 0, 1)
        for v in t:
            b += struct.pack('<3f', *v)
        b += b'\x00\x00'
    return b


def box(x0, y0, z0, x1, y1, z1):
    c = [(x, y, z) for z in (z0, z1) for y in (y0, y1) for x in (x0, x1)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    out = []
    for a, b, cc, d in quads:
        out += [(c[a], c[b], c[cc]), (c[a], c[cc], c[d])]
    return out


def dome(n=6, r=10.0, h=4.0):
    """A faceted dome: rings of triangles, heights varying across the grid."""
    tris = []
    for i in range(n):
        a0, a1 = 2 * math.pi * i / n, 2 * math.pi * (i + 1) / n
        p0 = (round(r * math.cos(a0), 3), round(r * math.sin(a0), 3), 0.0)
        p1 = (round(r * math.cos(a1), 3), round(r * math.sin(a1), 3), 0.0)
        tris.append(((0.0, 0.0, h), p0, p1))
    return tris


def stl_seeds():
    write('stl', 'pocket_design.stl', read(os.path.join(ROOT, 'tests/run/pocket_design.stl')).encode('latin-1'))
    write('stl', 'blank_step.stl', read(os.path.join(ROOT, 'tests/run/blank_step.stl')).encode('latin-1'))
    write('stl', 'box_ascii.stl', stl_ascii(box(0, 0, -5, 20, 12, 0), 'box'))
    write('stl', 'dome_ascii.stl', stl_ascii(dome()).replace(b'solid part', b'SOLID part', 1))
    write('stl', 'box_binary.stl', stl_binary(box(-3, -3, -10, 30, 25, 0)))
    write('stl', 'dome_binary.stl', stl_binary(dome(12, 15.0, 6.0)))
    write('stl', 'vertical_binary.stl', stl_binary([((0, 0, 0), (10, 0, 0), (10, 0, 5)), ((0, 0, 0), (10, 10, 1), (0, 10, 2))]))


def pgm_seeds():
    w, h = 6, 4
    px = [[(x * 40 + y * 25) % 256 for x in range(w)] for y in range(h)]
    write('pgm', 'p2_8bit.pgm', ('P2\n# a ramp\n%d %d\n255\n' % (w, h) +
                                 '\n'.join(' '.join(str(v) for v in row) for row in px) + '\n').encode())
    write('pgm', 'p5_8bit.pgm', b'P5\n%d %d\n255\n' % (w, h) + bytes(v for row in px for v in row))
    px16 = [[(x * 9000 + y * 7000) % 65536 for x in range(w)] for y in range(h)]
    write('pgm', 'p2_16bit.pgm', ('P2\n%d %d\n65535\n' % (w, h) +
                                  '\n'.join(' '.join(str(v) for v in row) for row in px16) + '\n').encode())
    write('pgm', 'p5_16bit.pgm', b'P5 %d %d # comment\n65535\n' % (w, h) +
          b''.join(struct.pack('>H', v) for row in px16 for v in row))
    write('pgm', 'p5_maxval_1.pgm', b'P5\n3 2\n1\n' + bytes([0, 1, 1, 0, 0, 1]))
    write('pgm', 'half.pgm', b'P5\n# design\n2 1\n255\n\xff\x00')


def main():
    demo = sys.argv[1] if len(sys.argv) > 1 else None
    for target in ('pipeline', 'tool_table', 'stl', 'pgm'):
        d = os.path.join(SEEDS, target)
        if os.path.isdir(d):
            for name in os.listdir(d):
                os.remove(os.path.join(d, name))
    pipeline_seeds(demo)
    tool_table_seeds()
    stl_seeds()
    pgm_seeds()


if __name__ == '__main__':
    main()
