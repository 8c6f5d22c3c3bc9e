#!/usr/bin/env python3
"""web_findings.py - the page's findings against dexmill run's, for
tools/scripts/web-test.sh: DIR/page.json's results carry `findings` (the
engine's, as the page lists them: name, line, atMm), DIR/cliK.err the K-th
native run's standard error, whose findings are warnings
"FILE:LINE:COL: warning: ... at XN YN ZN". For every case whose native run
warned of findings, the page's list holds the same lines and places (to the
micrometre the CLI prints), no more and no fewer; a case with findings must
have some (a check that finds nothing tests nothing). The others dexmill run
prints, "FILE:LINE:COL: warning: MESSAGE", are among the page's warnings
(line and column), and each of the page's has a message dexmill run prints
(a repeated one it folds into its first: "(N times, lines A to B)"). The
first finding clicked shows its program line under its text: "LINE | TEXT",
and a mark of its own over the frame, which a warning clicked takes away
(the frame, with the run's marks, is dexmill run's: web_compare.py).
Exit: 0 all equal, 1 otherwise.
"""
import json
import re
import sys

tmp = sys.argv[1]
page = json.load(open(tmp + "/page.json"))
WARN = re.compile(r":(\d+):\d+: warning: (rapid into material|cut with the spindle stopped|[^:]*below)[^\n]* at X(-?[\d.]+) Y(-?[\d.]+) Z(-?[\d.]+)")
bad = 0
for k, r in enumerate(page, 1):
    cli = [(int(m.group(1)), tuple(float(v) for v in m.group(3, 4, 5)))
           for m in WARN.finditer(open("%s/cli%d.err" % (tmp, k)).read())]
    err = open("%s/cli%d.err" % (tmp, k)).read()
    got = [(f["line"], tuple(round(v, 3) for v in f["atMm"])) for f in r.get("findings", [])]
    cli_warned = set((int(m.group(1)), int(m.group(2))) for m in re.finditer(r":(\d+):(\d+): warning: ", err)) - \
        set((l, 1) for l, _ in cli)
    page_warned = set((w["line"], w["col"]) for w in r.get("warnings", []))
    texts = all(": warning: " + w["message"] in err for w in r.get("warnings", []))
    if not cli_warned <= page_warned or not texts:
        print("web-test: case %d: the page's warnings %s, dexmill run's at %s" % (k, r.get("warnings"), sorted(cli_warned)),
              file=sys.stderr)
        bad = 1
    if sorted(cli) != sorted(got):
        print("web-test: case %d: the page's findings %s, dexmill run's %s" % (k, got, cli), file=sys.stderr)
        bad = 1
    elif cli and r.get("status") is not None:
        line = got[0][0]
        if not re.search(r"\n%d \| \S" % line, r["status"]):
            print("web-test: case %d: the clicked finding's status shows no line %d: %r" % (k, line, r["status"]), file=sys.stderr)
            bad = 1
        c = r.get("clicked", {})
        if c.get("marked") == c.get("before") or c.get("after") != c.get("before"):
            print("web-test: case %d: a finding clicked did not mark it, or a warning clicked did not clear it: %s" % (k, c),
                  file=sys.stderr)
            bad = 1
    if sorted(cli) == sorted(got) and cli:
        print("ok: web-test: case %d: %d findings, lines and places as dexmill run's (%s); %d warnings, its text"
              % (k, len(cli), ", ".join("line %d" % l for l, _ in cli), len(page_warned)))
sys.exit(bad)
