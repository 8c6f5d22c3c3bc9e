#!/usr/bin/env python3
"""The moves of LinuxCNC's own preview of a program, for the oracle.

usage: lcnc_preview.py PROGRAM

LinuxCNC's stand-alone interpreter `rs274` prints a spline (G5, G5.1) as
`NURBS_FEED(3, ...)`, without its points. Its preview (the `gcode` Python
module of linuxcnc-uspace, what AXIS draws with: gcodemodule.cc) runs the
same interpreter and draws each such curve as 15 straight feeds per control
point, every point on the curve. This prints those moves so that
lcnc_compare.py (--preview) can put the curve in place of NURBS_FEED:

    LINE KIND X Y Z

one per move, KIND rapid, feed, arc or probe, LINE the program line that
made it, X Y Z its end in machine millimetres (program coordinates plus the
G5x and G92 offsets, full precision). The module is built for the system's
Python 3 (/usr/bin/python3); under another Python the script runs itself
there. Exit 2 when the module is missing.
"""
import os
import shutil
import sys
import tempfile

MM_PER_INCH = 25.4

try:
    import gcode
except ImportError:
    if sys.executable != '/usr/bin/python3' and os.path.exists('/usr/bin/python3'):
        os.execv('/usr/bin/python3', ['/usr/bin/python3'] + sys.argv)
    print('lcnc_preview: LinuxCNC\'s gcode module is not installed (Debian package linuxcnc-uspace)',
          file=sys.stderr)
    sys.exit(2)


class Canon:
    """The preview's canon: records moves; every other call is a no-op."""

    parameter_file = ''  # no .var file

    def __init__(self):
        self.line = 0
        self.g5x = [0.0, 0.0, 0.0]
        self.g92 = [0.0, 0.0, 0.0]
        self.plane = 1  # CANON_PLANE_XY = 1, YZ = 2, XZ = 3
        self.moves = []

    # The preview passes inches (millimetres divided by 25.4), offsets too.
    def machine(self, x, y, z):
        return [(v + self.g5x[k] + self.g92[k]) * MM_PER_INCH for k, v in enumerate((x, y, z))]

    def next_line(self, linecode):
        self.line = linecode.sequence_number

    def set_g5x_offset(self, index, x, y, z, *rest):
        self.g5x = [x, y, z]

    def set_g92_offset(self, x, y, z, *rest):
        self.g92 = [x, y, z]

    def set_plane(self, plane):
        self.plane = plane

    def straight_traverse(self, x, y, z, *rest):
        self.moves.append((self.line, 'rapid', self.machine(x, y, z)))

    def straight_feed(self, x, y, z, *rest):
        self.moves.append((self.line, 'feed', self.machine(x, y, z)))

    def straight_probe(self, x, y, z, *rest):
        self.moves.append((self.line, 'probe', self.machine(x, y, z)))

    def arc_feed(self, first_end, second_end, first_axis, second_axis, rotation, axis_end, *rest):
        if self.plane == 2:    # YZ: (Y, Z), axis X
            x, y, z = axis_end, first_end, second_end
        elif self.plane == 3:  # XZ: (Z, X), axis Y
            x, y, z = second_end, axis_end, first_end
        else:
            x, y, z = first_end, second_end, axis_end
        self.moves.append((self.line, 'arc', self.machine(x, y, z)))

    def get_tool(self, pocket):
        # Every tool exists, of length 0 (as oracle-check's rs274 tool table).
        return (pocket, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0)

    def get_axis_mask(self):
        return 7  # X, Y, Z

    def get_external_length_units(self):
        return 1.0

    def get_external_angular_units(self):
        return 1.0

    def get_block_delete(self):
        return False

    def check_abort(self):
        return False

    def __getattr__(self, name):
        return lambda *args: None


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    canon = Canon()
    # LinuxCNC keeps its tool data in $HOME/.tool.mmap, shared by every
    # interpreter running at the time: a HOME of our own keeps theirs out.
    home = tempfile.mkdtemp()
    os.environ['HOME'] = home
    # rs274 starts in millimetres (so does dexmill); the preview in the
    # machine's units unless told.
    result, line = gcode.parse(sys.argv[1], canon, 'G21', '')
    for ln, kind, p in canon.moves:
        print('%d %s %.12f %.12f %.12f' % (ln, kind, p[0], p[1], p[2]))
    if result > gcode.MIN_ERROR:
        print('# stopped at line %d: %s' % (line, gcode.strerror(result)))
    shutil.rmtree(home, ignore_errors=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
