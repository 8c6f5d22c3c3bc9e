#!/usr/bin/env python3
"""web_controls.py - the page's controls in tools/scripts/web-test.sh's
cases (DIR/page.json): a replay at N times machine time (`speed`) took at
least the machine time / N plus the 300 ms it was paused, and the cut stood
still while paused (the status line the same before and after); a zoom
(`zoom`: the frame's hash after each step) came back: 10 wheel notches in
change the frame and 10 out give it back, a pinch gives the wheel's frame,
reset view the first; the keys (`keys`: 1 the iso view, + and - a zoom in
and out about the centre, then 2 the top view) changed the frame and gave
the top view's back (the frame after them is dexmill run --view top's,
web_compare.py); a file dropped on the canvas (`drop`) ran, from the file
input it was put into. Exit: 0 all held, 1 otherwise.
"""
import json
import sys

bad = 0
for k, r in enumerate(json.load(open(sys.argv[1] + "/page.json")), 1):
    if "speed" in r:
        need = r["progress"]["machineSeconds"] * 1000 / r["speed"]
        p = r["paused"]
        if r["ms"] < need + 300 or p["before"] != p["after"] or "machine time" not in p["before"]:
            print("web-test: case %d: %.0f ms for %.0f ms of machine time and 300 ms paused; paused %s"
                  % (k, r["ms"], need, p), file=sys.stderr)
            bad = 1
        else:
            print("ok: web-test: case %d: a replay at %dx took %.0f ms (machine time %.1f s / %d = %.0f ms, paused "
                  "300 ms, the cut still while paused)" % (k, r["speed"], r["ms"], r["progress"]["machineSeconds"],
                                                            r["speed"], need))
    z = r.get("zoom")
    if z:
        if z["wheelIn"] != z["before"] and z["wheelOut"] == z["before"] and z["pinch"] == z["wheelIn"] \
                and z["reset"] == z["before"]:
            print("ok: web-test: case %d: 10 notches in and out give the frame before; a pinch the wheel's frame; "
                  "reset the first" % k)
        else:
            print("web-test: case %d: zoom: %s" % (k, z), file=sys.stderr)
            bad = 1
    if "dropped" in r:
        if r["dropped"] == "dropped.ngc":
            print("ok: web-test: case %d: a file dropped on the canvas ran from the file input" % k)
        else:
            print("web-test: case %d: a dropped file: the file input holds %r" % (k, r["dropped"]), file=sys.stderr)
            bad = 1
    keys = r.get("keys")
    if keys:
        if keys["iso"] != keys["before"] and keys["zoomed"] != keys["iso"] and keys["after"] == keys["before"]:
            print("ok: web-test: case %d: the keys 1, +, - and 2 turn to iso, zoom in and out, and back to the top view" % k)
        else:
            print("web-test: case %d: keys: %s" % (k, keys), file=sys.stderr)
            bad = 1
sys.exit(bad)
