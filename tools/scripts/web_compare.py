#!/usr/bin/env python3
"""web_compare.py - the page's frames against dexmill run's, for
tools/scripts/web-test.sh and web-stream-test.sh: DIR/page.json is the
page's list of results (width, height, hash and shownHash, the FNV-1a the
page computed and showed, rgb its canvas's R, G, B bytes as base64, ms),
DIR/native.txt a line "PROGRAM|SIZE|VIEW|LOOK|MS" for each, DIR/cliK.ppm the
K-th native image (from 1). Each pair must be equal byte for byte, and the
page's hash that of its pixels; the first differing pixel is named.
Exit: 0 all equal, 1 otherwise.
"""
import base64
import json
import sys

tmp = sys.argv[1]
page = json.load(open(tmp + "/page.json"))
native = [l.split("|") for l in open(tmp + "/native.txt").read().split("\n") if l]

def fnv1a(data):
    h = 0x811c9dc5
    for b in data:
        h = ((h ^ b) * 16777619) & 0xffffffff
    return "%08x" % h

def ppm(path):
    raw = open(path, "rb").read()
    fields, at = [], 0
    while len(fields) < 4:  # P6, width, height, maxval; one whitespace byte after the last
        while raw[at:at + 1].isspace():
            at += 1
        start = at
        while not raw[at:at + 1].isspace():
            at += 1
        fields.append(raw[start:at])
    assert fields[0] == b"P6" and fields[3] == b"255", path
    return int(fields[1]), int(fields[2]), raw[at + 1:]

bad = 0
assert len(page) == len(native), "cases: %d in the page, %d native" % (len(page), len(native))
for k, (r, (prog, size, view, look, ms)) in enumerate(zip(page, native), 1):
    w, h, cli = ppm("%s/cli%d.ppm" % (tmp, k))
    got = base64.b64decode(r["rgb"])
    what = "%s %s %s %s" % (prog, size, view, look)
    if (w, h) != (r["width"], r["height"]) or len(got) != len(cli):
        print("web: %s: the page's frame is %dx%d, dexmill run's %dx%d" % (what, r["width"], r["height"], w, h))
        bad = 1
        continue
    if fnv1a(got) != r["hash"] or r["shownHash"] != r["hash"]:
        print("web: %s: the page's hash %s (shown %s) is not that of its pixels, %s" %
              (what, r["hash"], r["shownHash"], fnv1a(got)))
        bad = 1
    if got != cli:
        i = next(i for i in range(len(got)) if got[i] != cli[i]) // 3
        diff = sum(1 for i in range(0, len(got), 3) if got[i:i + 3] != cli[i:i + 3])
        print("web: %s: %d pixels differ, the first at (%d, %d): page %s, dexmill run %s" %
              (what, diff, i % w, i // w, got[3 * i:3 * i + 3].hex(), cli[3 * i:3 * i + 3].hex()))
        bad = 1
        continue
    print("ok: web: %s: the page's canvas is dexmill run's image, byte for byte (FNV-1a %s); "
          "the job in the page %.0f ms, dexmill run %s ms (the whole process)" % (what, r["hash"], r["ms"], ms))
sys.exit(bad)
