#!/usr/bin/env python3
"""Compare `dexmill path` output with a LinuxCNC canonical trace.

usage: lcnc_compare.py TRACE PATHFILE [--tol MM]

TRACE is what LinuxCNC's interpreter prints (the `expected` files of
tests/interp, or `rs274 -g FILE`): STRAIGHT_TRAVERSE / STRAIGHT_FEED /
ARC_FEED in program units and in the coordinate system in force, with
SET_G5X_OFFSET, SET_G92_OFFSET and USE_LENGTH_UNITS telling how to get to
machine millimetres. The tool length offset is not added (dexmill's path
does not apply it either). ARC_FEED(first_end, second_end, first_centre,
second_centre, rotation, axis_end, ...) is in the plane of SELECT_PLANE:
(X, Y) for XY, (Z, X) for XZ, (Y, Z) for YZ; rotation > 0 is
counterclockwise, |rotation| - 1 extra full turns, and an end equal to the
start (as printed) is a full circle.

Every dexmill point must lie within TOL (plus LinuxCNC's own print rounding
for inch traces, 0.0022 mm) of the LinuxCNC move it belongs to
(the arc or helix itself for chord points), every LinuxCNC move end must be
met within TOL, in order, with the same kind (rapid/feed). Zero-length moves
are ignored on both sides. Prints one summary line; exit 0 if they agree.
"""
import math
import re
import sys

MM_PER_INCH = 25.4
CALL = re.compile(r'^\s*(?:\d+\s+)?N\S*\s+([A-Z_0-9]+)\((.*)\)\s*$')


def parse_trace(path):
    """Moves in machine mm: (kind, start, end, arc) with arc = None or a dict."""
    scale = 1.0
    g5x = [0.0, 0.0, 0.0]
    g92 = [0.0, 0.0, 0.0]
    plane = 'XY'
    pos = None  # program-frame point as printed, in mm (machine = pos + offsets)
    cur_machine = [0.0, 0.0, 0.0]
    moves = []
    error = None
    notes = []
    with open(path, encoding='utf-8', errors='replace') as f:
        lines = f.read().splitlines()
    for i, line in enumerate(lines):
        m = CALL.match(line)
        if not m:
            s = line.strip()
            if s and s != 'executing' and error is None and not s.startswith('N..'):
                error = s
            continue
        name, args = m.group(1), m.group(2)
        if name == 'USE_LENGTH_UNITS':
            scale = MM_PER_INCH if 'INCH' in args else 1.0
            continue
        if name == 'SELECT_PLANE':
            plane = 'XY' if 'XY' in args else ('XZ' if 'XZ' in args else 'YZ')
            continue
        if name == 'COMMENT':
            continue
        nums = []
        for a in re.split(r'[,\s]+', args):
            try:
                nums.append(float(a))
            except ValueError:
                pass
        if name == 'SET_G5X_OFFSET':
            g5x = [v * scale for v in nums[1:4]]
        elif name == 'SET_G92_OFFSET':
            g92 = [v * scale for v in nums[0:3]]
        elif name == 'SET_XY_ROTATION':
            if nums and abs(nums[0]) > 1e-12:
                notes.append('XY rotation %g not handled' % nums[0])
        elif name in ('STRAIGHT_TRAVERSE', 'STRAIGHT_FEED', 'STRAIGHT_PROBE'):
            p = [nums[k] * scale + g5x[k] + g92[k] for k in range(3)]
            kind = 'rapid' if name == 'STRAIGHT_TRAVERSE' else 'feed'
            moves.append((kind, cur_machine, p, None, scale != 1.0))
            cur_machine = p
            pos = [nums[k] for k in range(3)]
        elif name == 'ARC_FEED':
            fe, se, fc, sc, rot, ae = nums[0:6]
            off = [g5x[k] + g92[k] for k in range(3)]
            idx = {'XY': (0, 1, 2), 'XZ': (2, 0, 1), 'YZ': (1, 2, 0)}[plane]
            end = [0.0, 0.0, 0.0]
            end[idx[0]] = fe * scale + off[idx[0]]
            end[idx[1]] = se * scale + off[idx[1]]
            end[idx[2]] = ae * scale + off[idx[2]]
            centre = (fc * scale + off[idx[0]], sc * scale + off[idx[1]])
            # Full circle when the printed end equals the printed start.
            full = pos is not None and abs(pos[idx[0]] - fe) < 1e-12 and abs(pos[idx[1]] - se) < 1e-12
            arc = dict(idx=idx, centre=centre, rot=int(rot), full=full)
            moves.append(('feed', cur_machine, end, arc, scale != 1.0))
            cur_machine = end
            p = [0.0, 0.0, 0.0]
            p[idx[0]], p[idx[1]], p[idx[2]] = fe, se, ae
            pos = p
    return moves, error, notes


def parse_path(path):
    pts = []
    start = None
    with open(path) as f:
        for line in f:
            if line.startswith('# start'):
                start = [float(v) for v in line.split()[2:5]]
                continue
            if line.startswith('#') or not line.strip():
                continue
            k, x, y, z = line.split()
            pts.append((k, [float(x), float(y), float(z)]))
    return start, pts


def dist(a, b):
    return math.sqrt(sum((a[k] - b[k]) ** 2 for k in range(3)))


class ArcGeom:
    def __init__(self, start, end, arc):
        i0, i1, i2 = arc['idx']
        self.idx = arc['idx']
        self.ca, self.cb = arc['centre']
        self.start, self.end = start, end
        self.a0 = math.atan2(start[i1] - self.cb, start[i0] - self.ca)
        a1 = math.atan2(end[i1] - self.cb, end[i0] - self.ca)
        self.r0 = math.hypot(start[i0] - self.ca, start[i1] - self.cb)
        self.r1 = math.hypot(end[i0] - self.ca, end[i1] - self.cb)
        rot = arc['rot']
        self.dir = 1 if rot > 0 else -1
        base = (a1 - self.a0) * self.dir
        base %= 2 * math.pi
        if arc['full'] or base < 1e-12:
            base = 2 * math.pi if arc['full'] else base
        self.sweep = base + (abs(rot) - 1) * 2 * math.pi
        self.c0, self.c1 = start[i2], end[i2]

    def at(self, t):
        ang = self.a0 + self.dir * self.sweep * t
        r = self.r0 + (self.r1 - self.r0) * t
        p = [0.0, 0.0, 0.0]
        i0, i1, i2 = self.idx
        p[i0] = self.ca + r * math.cos(ang)
        p[i1] = self.cb + r * math.sin(ang)
        p[i2] = self.c0 + (self.c1 - self.c0) * t
        return p

    def progress(self, p, t_prev):
        """Parameter t of point p, continuing from t_prev (angles unwrapped)."""
        i0, i1, _ = self.idx
        if self.sweep <= 0:
            return 1.0
        ang = math.atan2(p[i1] - self.cb, p[i0] - self.ca)
        prev_ang = self.a0 + self.dir * self.sweep * t_prev
        d = (ang - prev_ang) * self.dir
        d = (d + math.pi) % (2 * math.pi) - math.pi
        return t_prev + d / self.sweep


def seg_dist(p, s, e):
    d = [e[k] - s[k] for k in range(3)]
    l2 = sum(v * v for v in d)
    t = 0.0 if l2 == 0 else max(0.0, min(1.0, sum((p[k] - s[k]) * d[k] for k in range(3)) / l2))
    return dist(p, [s[k] + t * d[k] for k in range(3)]), t


def compare_strict(moves, start, pts, tol, inch_tol):
    """One dexmill point per LinuxCNC straight move (zero-length ones too:
    both print every move), chord points for each arc."""
    j = 0
    worst = 0.0
    for mi, (kind, s, e, arc, inch) in enumerate(moves):
        t_ol = tol + (inch_tol if inch else 0.0)
        if j >= len(pts):
            return False, worst, 'dexmill path ends before LinuxCNC move %d' % (mi + 1)
        if arc is None:
            k, p = pts[j]
            dd = dist(p, e)
            worst = max(worst, dd)
            if k != kind or dd > t_ol:
                return False, worst, 'move %d: LinuxCNC %s %s, dexmill %s %s' % (mi + 1, kind, fmt(e), k, fmt(p))
            j += 1
            continue
        g = ArcGeom(s, e, arc)
        t = 0.0
        while True:
            if j >= len(pts):
                return False, worst, 'dexmill path ends inside LinuxCNC arc %d' % (mi + 1)
            k, p = pts[j]
            t = g.progress(p, t)
            dd = dist(p, g.at(min(max(t, 0.0), 1.0)))
            worst = max(worst, dd)
            if k != 'feed' or dd > t_ol:
                return False, worst, 'move %d: point %s %s is %.5f mm off the LinuxCNC arc' % (mi + 1, k, fmt(p), dd)
            j += 1
            if t >= 1.0 - 1e-9 or (dist(p, e) <= t_ol and (1.0 - t) * g.sweep * max(g.r0, g.r1) <= t_ol):
                worst = max(worst, dist(p, e))
                if dist(p, e) > t_ol:
                    return False, worst, 'move %d: arc ends at %s, LinuxCNC at %s' % (mi + 1, fmt(p), fmt(e))
                break
    if j < len(pts):
        return None, worst, '%d moves agree; dexmill has %d more point(s) after LinuxCNC ends, first %s %s' % (
            len(moves), len(pts) - j, pts[j][0], fmt(pts[j][1]))
    return True, worst, '%d moves' % len(moves)


def compare(moves, start, pts, tol, inch_tol):
    """Walks LinuxCNC's moves in order, consuming dexmill's points that lie on
    each move (within tolerance, moving forwards); each move's end must be met.
    Moves shorter than the tolerance may be met by no point at all (LinuxCNC
    prints 4 decimals, so tiny moves can vanish or appear on either side)."""
    ours = []
    prev = start
    for k, p in pts:
        if dist(p, prev) > 1e-9:
            ours.append((k, p))
        prev = p
    j = 0
    worst = 0.0
    last = start
    for mi, (kind, s, e, arc, inch) in enumerate(moves):
        t_ol = tol + (inch_tol if inch else 0.0)
        # Points of ours within tolerance of where we are (a tiny move that
        # LinuxCNC's rounding made vanish) belong to no move of its.
        while j < len(ours) and dist(ours[j][1], last) <= t_ol and dist(ours[j][1], e) > t_ol:
            j += 1
        if arc is None:
            length = dist(s, e)
            if length <= t_ol and dist(last, e) <= t_ol:
                while j < len(ours) and dist(ours[j][1], e) <= t_ol:
                    last = ours[j][1]
                    j += 1
                continue
            t_prev = -1.0
            while j < len(ours):
                k, p = ours[j]
                dd, t = seg_dist(p, s, e)
                if dd > t_ol or t < t_prev - 1e-9:
                    break
                if k != kind and length > t_ol:
                    return False, worst, 'move %d: LinuxCNC %s to %s, dexmill %s %s' % (mi + 1, kind, fmt(e), k, fmt(p))
                worst = max(worst, dd)
                j += 1
                last = p
                t_prev = t
                if dist(p, e) <= t_ol:
                    break
            de = dist(last, e)
            if de > t_ol:
                nxt = ('%s %s' % (ours[j][0], fmt(ours[j][1]))) if j < len(ours) else 'the end of the path'
                return False, worst, 'move %d: LinuxCNC %s to %s; dexmill at %s, then %s' % (
                    mi + 1, kind, fmt(e), fmt(last), nxt)
            worst = max(worst, de)
            continue
        g = ArcGeom(s, e, arc)
        if g.sweep * max(g.r0, g.r1) <= t_ol and dist(last, e) <= t_ol and not arc['full']:
            while j < len(ours) and dist(ours[j][1], e) <= t_ol:
                last = ours[j][1]
                j += 1
            continue
        t = 0.0
        while True:
            if j >= len(ours):
                return False, worst, 'dexmill path ends inside LinuxCNC arc %d (to %s)' % (mi + 1, fmt(e))
            k, p = ours[j]
            if k != 'feed':
                return False, worst, 'move %d: LinuxCNC arc to %s, dexmill %s %s' % (mi + 1, fmt(e), k, fmt(p))
            t = g.progress(p, t)
            dd = dist(p, g.at(min(max(t, 0.0), 1.0)))
            worst = max(worst, dd)
            if dd > t_ol:
                return False, worst, 'move %d: chord point %s is %.5f mm off the LinuxCNC arc' % (mi + 1, fmt(p), dd)
            j += 1
            last = p
            if t >= 1.0 - 1e-9 or (dist(p, e) <= t_ol and (1.0 - t) * g.sweep * max(g.r0, g.r1) <= t_ol):
                de = dist(p, e)
                worst = max(worst, de)
                if de > t_ol:
                    return False, worst, 'move %d: arc ends at %s, LinuxCNC at %s' % (mi + 1, fmt(p), fmt(e))
                break
    rest = [q for q in ours[j:] if dist(q[1], last) > tol]
    if rest:
        return None, worst, '%d moves agree; dexmill has %d more point(s) after LinuxCNC ends, first %s %s' % (
            len(moves), len(ours) - j, rest[0][0], fmt(rest[0][1]))
    return True, worst, '%d moves' % len(moves)


def fmt(p):
    return '(%.4f, %.4f, %.4f)' % tuple(p)


def main():
    args = sys.argv[1:]
    tol = 0.002
    if '--tol' in args:
        i = args.index('--tol')
        tol = float(args[i + 1])
        del args[i:i + 2]
    if len(args) != 2:
        print(__doc__)
        return 2
    moves, error, notes = parse_trace(args[0])
    start, pts = parse_path(args[1])
    # LinuxCNC prints 4 decimals: in inch that is 0.00005 in (1.27 um) of
    # rounding per coordinate, up to 0.0022 mm in 3D, added to the tolerance.
    inch_tol = 0.00005 * MM_PER_INCH * math.sqrt(3)
    ok, worst, msg = compare_strict(moves, start or [0.0, 0.0, 0.0], pts, tol, inch_tol)
    if ok is False:
        # Fall back to matching by geometry (tolerates a move more or less
        # on either side, e.g. LinuxCNC's traverse for a bare G0).
        ok2, worst2, msg2 = compare(moves, start or [0.0, 0.0, 0.0], pts, tol, inch_tol)
        if ok2 is not False:
            ok, worst, msg = ok2, worst2, msg2 + ' (matched by geometry)'
        else:
            msg = msg + ' | by geometry: ' + msg2
    status = 'AGREE' if ok else 'DIFFER'
    if ok is None:
        # LinuxCNC stopped early (an error) and dexmill went on: the common
        # part agrees; the reason is in the bracket below.
        status = 'AGREE-UNTIL-LINUXCNC-STOPS' if error else 'DIFFER'
        ok = bool(error)
    extra = ''
    if error:
        extra += ' [LinuxCNC stopped: %s]' % error
    if notes:
        extra += ' [' + '; '.join(notes) + ']'
    print('%s: %s, max deviation %.5f mm%s' % (status, msg, worst, extra))
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
