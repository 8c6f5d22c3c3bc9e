#!/usr/bin/env python3
"""Compare `dexmill path` output with a LinuxCNC canonical trace.

usage: lcnc_compare.py TRACE PATHFILE [--tol MM] [--preview MOVES]

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

A spline (G5, G5.1) is only NURBS_FEED(order, ...) in the trace, without
points. With --preview MOVES (what lcnc_preview.py prints: LinuxCNC's own
preview of the program, the same interpreter, whose points lie on each
curve) every NURBS_FEED becomes the Bezier curve through those points
(control points fitted by least squares, at the preview's parameters), and
dexmill's chord points must lie within TOL of it, in order, like an arc's.
Without it, a trace with NURBS_FEED is not comparable (exit 3).
"""
import math
import re
import sys

MM_PER_INCH = 25.4
CALL = re.compile(r'^\s*(?:\d+\s+)?N\S*\s+([A-Z_0-9]+)\((.*)\)\s*$')


def machine(nums, scale, g5x, g92, rot):
    """A printed point in machine mm: rot(program + G92) + G5x (LinuxCNC's
    canon, rotate_and_offset)."""
    p = [nums[k] * scale + g92[k] for k in range(3)]
    if rot:
        c, s = math.cos(rot), math.sin(rot)
        p = [p[0] * c - p[1] * s, p[0] * s + p[1] * c, p[2]]
    return [p[k] + g5x[k] for k in range(3)]


def turned(p, turn):
    """p turned about the G5x origin (turn = (radians, ox, oy)), or p."""
    if not turn:
        return p
    a, ox, oy = turn
    c, s = math.cos(a), math.sin(a)
    return [ox + (p[0] - ox) * c - (p[1] - oy) * s, oy + (p[0] - ox) * s + (p[1] - oy) * c, p[2]]


def unturn(p, turn):
    return turned(p, (-turn[0], turn[1], turn[2]))


def parse_trace(path):
    """Moves in machine mm: (kind, start, end, arc) with arc = None or a dict."""
    scale = 1.0
    g5x = [0.0, 0.0, 0.0]
    g92 = [0.0, 0.0, 0.0]
    plane = 'XY'
    xy_rot = 0.0  # XY rotation of the system in force, radians (G10 L2 R)
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
        if name == 'NURBS_FEED':
            # The curve's points come from the preview (attach_curves).
            order = int(args.split(',')[0])
            moves.append(('feed', cur_machine, None, dict(nurbs=order), scale != 1.0))
            pos = None
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
            xy_rot = math.radians(nums[0]) if nums else 0.0
        elif name in ('STRAIGHT_TRAVERSE', 'STRAIGHT_FEED', 'STRAIGHT_PROBE'):
            p = machine(nums, scale, g5x, g92, xy_rot)
            kind = 'rapid' if name == 'STRAIGHT_TRAVERSE' else 'feed'
            moves.append((kind, cur_machine, p, None, scale != 1.0))
            cur_machine = p
            pos = [nums[k] for k in range(3)]
        elif name == 'RIGID_TAP':
            # G33.1: in to the point and back out to where it began; the
            # position stays (LinuxCNC's interpreter does not move it).
            p = machine(nums, scale, g5x, g92, xy_rot)
            moves.append(('feed', cur_machine, p, None, scale != 1.0))
            moves.append(('feed', p, cur_machine, None, scale != 1.0))
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
            turn = None
            if xy_rot and plane == 'XY':  # LinuxCNC's canon turns XY arcs' points about the G5x origin
                end = machine([end[k] - g5x[k] for k in range(3)], 1.0, g5x, [0, 0, 0], xy_rot)
                c = machine([centre[0] - g5x[0], centre[1] - g5x[1], 0], 1.0, g5x, [0, 0, 0], xy_rot)
                centre = (c[0], c[1])
            elif xy_rot:  # a G18/G19 arc turned out of its plane: kept unturned, turned point by point
                turn = (xy_rot, g5x[0], g5x[1])
            arc = dict(idx=idx, centre=centre, rot=int(rot), full=full, turn=turn)
            start = cur_machine
            if turn:
                start = unturn(cur_machine, turn)
            arc['start0'] = start
            moves.append(('feed', cur_machine, turned(end, turn), arc, scale != 1.0))
            end = turned(end, turn)
            cur_machine = end
            p = [0.0, 0.0, 0.0]
            p[idx[0]], p[idx[1]], p[idx[2]] = fe, se, ae
            pos = p
    return moves, error, notes


def read_preview(path):
    """lcnc_preview.py's moves: (line, kind, end in machine mm)."""
    out = []
    with open(path) as f:
        for line in f:
            if line.startswith('#') or not line.strip():
                continue
            ln, kind, x, y, z = line.split()
            out.append((int(ln), kind, [float(x), float(y), float(z)]))
    return out


def bernstein(n, u):
    """The Bernstein polynomials of degree n at u."""
    return [math.comb(n, i) * u ** i * (1 - u) ** (n - i) for i in range(n + 1)]


def bezier_at(ctrl, u):
    b = bernstein(len(ctrl) - 1, u)
    return [sum(b[i] * ctrl[i][k] for i in range(len(ctrl))) for k in range(3)]


def fit_bezier(start, pts, order):
    """Control points of the Bezier curve of `order` control points that
    starts at `start` and passes through pts[i] at u = (i + 1) / div (the
    preview's steps, gcodemodule.cc: div = 15 per control point), the last at
    u = 1: the inner ones by least squares, the ends as given. Also the
    largest distance of a point from the fitted curve."""
    deg = order - 1
    div = 15 * order
    params = [(i + 1) / div for i in range(len(pts) - 1)] + [1.0]
    end = pts[-1]
    inner = deg - 1
    ctrl = [list(start)] + [[0.0, 0.0, 0.0] for _ in range(inner)] + [list(end)]
    for axis in range(3):
        a = [[0.0] * inner for _ in range(inner)]  # normal equations
        rhs = [0.0] * inner
        for u, p in zip(params, pts):
            b = bernstein(deg, u)
            r = p[axis] - b[0] * start[axis] - b[deg] * end[axis]
            for i in range(inner):
                rhs[i] += b[i + 1] * r
                for j in range(inner):
                    a[i][j] += b[i + 1] * b[j + 1]
        for i in range(inner):  # Gauss-Jordan: at most 2 x 2, well conditioned
            for j in range(inner):
                if j != i:
                    f = a[j][i] / a[i][i]
                    for k in range(inner):
                        a[j][k] -= f * a[i][k]
                    rhs[j] -= f * rhs[i]
        for i in range(inner):
            ctrl[i + 1][axis] = rhs[i] / a[i][i]
    worst = max(dist(p, bezier_at(ctrl, u)) for u, p in zip(params, pts))
    return ctrl, worst


def attach_curves(moves, preview):
    """Puts the preview's curve in place of each NURBS_FEED. The preview's
    moves are rs274's one for one, except that a NURBS_FEED is all the feeds
    of its line. Returns (moves with their starts recomputed, None) or
    (None, why not)."""
    out = []
    j = 0
    prev_end = [0.0, 0.0, 0.0]
    exact = [0.0, 0.0, 0.0]  # the preview's point there, unrounded (rs274 prints 4 decimals)
    for mi, (kind, s, e, arc, inch) in enumerate(moves):
        if j >= len(preview):
            return None, 'the preview ends before LinuxCNC move %d' % (mi + 1)
        if arc is not None and 'nurbs' in arc:
            line = preview[j][0]
            pts = []
            while j < len(preview) and preview[j][0] == line and preview[j][1] == 'feed':
                pts.append(preview[j][2])
                j += 1
            ctrl, worst = fit_bezier(exact, pts, arc['nurbs'])
            if worst <= 1e-6:  # a spline (G5, G5.1): one Bezier curve
                arc = dict(curve=ctrl)
            else:
                # A G5.2 NURBS, of more spans than one Bezier: the preview's
                # points (exact, 15 per control point) joined by chords, which
                # is as close as their sagitta (small for the project's
                # programs' curves).
                arc = dict(polyline=[list(exact)] + pts)
            e = exact = pts[-1]
        else:
            want = 'arc' if arc is not None else ('rapid' if kind == 'rapid' else None)
            got = preview[j][1]
            if (want and got != want) or (not want and got not in ('feed', 'probe')) or dist(preview[j][2], e) > 0.01:
                return None, 'the preview differs from rs274 at move %d (%s %s; preview %s %s)' % (
                    mi + 1, kind, fmt(e), got, fmt(preview[j][2]))
            exact = preview[j][2]
            j += 1
        out.append((kind, prev_end, e, arc, inch))
        prev_end = e
    return out, None


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
        self.turn = arc.get('turn')
        if self.turn:  # worked unturned, turned point by point
            start, end = arc['start0'], unturn(end, self.turn)
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
        return turned(p, self.turn)

    def remaining(self, t):
        """The planar length left from t to the end (at the larger radius)."""
        return (1.0 - t) * self.sweep * max(self.r0, self.r1)

    def progress(self, p, t_prev):
        """Parameter t of point p, continuing from t_prev (angles unwrapped)."""
        i0, i1, _ = self.idx
        if self.sweep <= 0:
            return 1.0
        if self.turn:
            p = unturn(p, self.turn)
        ang = math.atan2(p[i1] - self.cb, p[i0] - self.ca)
        prev_ang = self.a0 + self.dir * self.sweep * t_prev
        d = (ang - prev_ang) * self.dir
        d = (d + math.pi) % (2 * math.pi) - math.pi
        return t_prev + d / self.sweep


class CurveGeom:
    """A Bezier curve (a spline's NURBS_FEED), with ArcGeom's interface."""

    SAMPLES = 256

    def __init__(self, start, end, arc):
        self.ctrl = arc['curve']
        self.start, self.end = start, end
        pts = [self.at(i / self.SAMPLES) for i in range(self.SAMPLES + 1)]
        # Length of the curve from u = i / SAMPLES to the end, for remaining().
        self.tail = [0.0] * (self.SAMPLES + 1)
        for i in range(self.SAMPLES - 1, -1, -1):
            self.tail[i] = self.tail[i + 1] + dist(pts[i], pts[i + 1])

    def at(self, t):
        return bezier_at(self.ctrl, t)

    def remaining(self, t):
        x = min(float(self.SAMPLES), max(0.0, t * self.SAMPLES))
        i = min(self.SAMPLES - 1, int(x))
        return self.tail[i] - (x - i) * (self.tail[i] - self.tail[i + 1])

    def progress(self, p, t_prev):
        """The parameter of the curve's point nearest p, from a little before
        t_prev on: sampled, then refined by golden sections."""
        lo = max(0.0, t_prev - 0.01)
        n = 200
        best = min(range(n + 1), key=lambda i: dist(p, self.at(lo + (1.0 - lo) * i / n)))
        a = lo + (1.0 - lo) * max(0, best - 1) / n
        b = lo + (1.0 - lo) * min(n, best + 1) / n
        for _ in range(60):
            m1, m2 = a + (b - a) * 0.382, a + (b - a) * 0.618
            if dist(p, self.at(m1)) <= dist(p, self.at(m2)):
                b = m2
            else:
                a = m1
        return (a + b) / 2


class PolylineGeom(CurveGeom):
    """The preview's points of a NURBS joined by chords, CurveGeom's interface."""

    def __init__(self, start, end, arc):
        self.pts = [arc['polyline'][0]]
        for q in arc['polyline'][1:]:  # the preview repeats the end point
            if dist(q, self.pts[-1]) > 1e-12:
                self.pts.append(q)
        super().__init__(start, end, dict(curve=None))

    def remaining(self, t):
        x = min(1.0, max(0.0, t)) * (len(self.pts) - 1)
        i = min(len(self.pts) - 2, int(x))
        rest = dist(self.at(t), self.pts[i + 1])
        return rest + sum(dist(self.pts[k], self.pts[k + 1]) for k in range(i + 1, len(self.pts) - 1))

    def at(self, t):
        x = min(1.0, max(0.0, t)) * (len(self.pts) - 1)
        i = min(len(self.pts) - 2, int(x))
        f = x - i
        a, b = self.pts[i], self.pts[i + 1]
        return [a[k] + (b[k] - a[k]) * f for k in range(3)]


def geometry(s, e, arc):
    if 'polyline' in arc:
        return PolylineGeom(s, e, arc)
    return CurveGeom(s, e, arc) if 'curve' in arc else ArcGeom(s, e, arc)


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
        g = geometry(s, e, arc)
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
            if t >= 1.0 - 1e-9 or (dist(p, e) <= t_ol and g.remaining(t) <= t_ol):
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
        g = geometry(s, e, arc)
        if g.remaining(0.0) <= t_ol and dist(last, e) <= t_ol and not arc.get('full'):
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
            if t >= 1.0 - 1e-9 or (dist(p, e) <= t_ol and g.remaining(t) <= t_ol):
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
    preview = None
    if '--preview' in args:
        i = args.index('--preview')
        preview = read_preview(args[i + 1])
        del args[i:i + 2]
    if len(args) != 2:
        print(__doc__)
        return 2
    moves, error, notes = parse_trace(args[0])
    start, pts = parse_path(args[1])
    if any(arc is not None and 'nurbs' in arc for _, _, _, arc, _ in moves):
        why = 'NURBS_FEED without --preview' if preview is None else None
        if preview is not None:
            moves, why = attach_curves(moves, preview)
        if why:
            print('NOT COMPARABLE: %s' % why)
            return 3
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
