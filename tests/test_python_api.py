"""The Python wrapper (tools/python/dexmill.py) over libdexmill.so: a program
simulated, its heights and findings read (a rapid into the stock, a gouge
under a design), input errors and warnings with their messages, bad input
raised as DexmillError, a view's frame equal to `dexmill run --image`'s, its
zoom, toolpath and mark.

Run by `make test` (DEXMILL_LIB: the library; DEXMILL: the binary, for the
frame comparison). Standard library only.
"""

import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tools", "python"))

import dexmill  # noqa: E402

with open(os.path.join(HERE, "run", "pocket.ngc")) as f:
    POCKET = f.read()
STOCK = (0, 0, -10, 33, 23, 0)
RAPID_INTO_STOCK = "G21 G90\nG0 X5 Y5 Z5\nM3 S1000\nG0 Z-1\nG0 X15\nG1 X20 F100\nM30\n"


class Heights(unittest.TestCase):
    def test_pocket(self):
        with dexmill.Simulation(STOCK, tool="flat:6", pitch_mm=0.1) as sim:
            self.assertEqual(sim.run(POCKET, piece=100, moves=2), "done")
            self.assertEqual(sim.height_mm(15, 7), -3.0)    # the pocket's floor
            self.assertEqual(sim.height_mm(31, 2), 0.0)     # uncut
            self.assertEqual(sim.height_mm("28", "18"), -8.0)  # the drilled hole
            self.assertIsNone(sim.column(100, 0))
            p = sim.progress()
            self.assertEqual(p["state"], "done")
            self.assertEqual(p["position_mm"][2], 10.0)
            self.assertGreater(p["removed_mm3"], 26 * 16 * 3)
            self.assertEqual(sim.grid()["pitch_mm"], 0.1)
            self.assertEqual(sim.findings(), [])


class Findings(unittest.TestCase):
    def test_rapid_into_stock(self):
        with dexmill.Simulation(STOCK, tool="flat:6", pitch_mm=0.2, checks=("rapid",)) as sim:
            self.assertEqual(sim.run(RAPID_INTO_STOCK), "done")
            f = sim.findings()
            self.assertGreaterEqual(len(f), 1)
            self.assertEqual(f[0]["kind"], "rapid")
            self.assertIn(f[0]["line"], (4, 5))

    def test_gouge_under_a_design(self):
        floor = [((-5, -5, -2), (40, -5, -2), (40, 30, -2)), ((-5, -5, -2), (40, 30, -2), (-5, 30, -2))]
        with dexmill.Simulation(STOCK, tool="flat:6", pitch_mm=0.1, design_mm=floor, provenance=True) as sim:
            self.assertEqual(sim.run(POCKET), "done")
            f = sim.findings()
            self.assertEqual(f[0]["kind"], "gouge")
            self.assertEqual(f[0]["line"], 10)  # the second pass, at Z-3
            self.assertAlmostEqual(f[0]["depth_mm"], 1.0)
            self.assertEqual(sim.column(15, 7)["last_tool"], -1)


class Errors(unittest.TestCase):
    def test_input_error(self):
        with dexmill.Simulation(STOCK, pitch_mm=0.5) as sim:
            for line in ("G21", "G1 X1 Q F100", "G0 Z1"):
                self.assertEqual(sim.step(), "need_input")
                sim.feed_line(line)
            sim.end_input()
            self.assertEqual(sim.step(), "stopped")
            e = sim.errors()
            self.assertEqual((e[0]["line"], e[0]["col"]), (2, 7))
            self.assertIn("'Q'", e[0]["message"])
            self.assertEqual(sim.progress()["stop_reason"], "input_error")

    def test_warnings(self):
        with dexmill.Simulation(STOCK, pitch_mm=0.5) as sim:
            self.assertEqual(sim.run("G21 G90\n$H\nG0 X1\nM2\n"), "done")
            w = sim.warnings()
            self.assertEqual((w[0]["line"], w[0]["col"]), (2, 1))
            self.assertIn("'$H'", w[0]["message"])

    def test_bad_job_raises(self):
        with self.assertRaises(dexmill.DexmillError) as c:
            dexmill.Simulation(STOCK, tool="spoon:6")
        self.assertEqual(c.exception.status, 6)
        with self.assertRaises(dexmill.DexmillError):
            dexmill.Simulation((0, 0, 0, 0, 10, 10))
        with self.assertRaises(dexmill.DexmillError):
            dexmill.nm("12mm")


class Views(unittest.TestCase):
    def test_frame_is_the_clis(self):
        with dexmill.Simulation(STOCK, tool="ball:6", grid=(165, 115)) as sim:
            view = sim.view(160, 120)
            redraws = []
            self.assertEqual(sim.run(POCKET, moves=3, each=lambda s: redraws.append(view.render())), "done")
            view.render()
            self.assertTrue(any(r and r[0] != (0, 0, 160, 120) for r in redraws))  # incremental
            rgb = view.rgb()
            self.assertGreater(len(set(rgb[k:k + 3] for k in range(0, len(rgb), 3))), 50)
            binary = os.environ.get("DEXMILL")
            if not binary:
                return
            with tempfile.TemporaryDirectory() as d:
                out = os.path.join(d, "f.ppm")
                # A view draws no axis triad or scale bar until asked (below),
                # and aliased (the CLI's stills are anti-aliased by default).
                subprocess.run([binary, "run", os.path.join(HERE, "run", "pocket.ngc"), "-q", "--no-decorations",
                                "--no-antialias", "--stock",
                                "0,0,-10,33,23,0", "--tool", "ball:6", "--grid", "165x115", "--size", "160x120",
                                "--image", out], check=True)
                with open(out, "rb") as f:
                    ppm = f.read()
            self.assertEqual(ppm, b"P6\n160 120\n255\n" + rgb)

    def test_zoom_path_and_mark(self):
        # Zoomed in about a pixel and back out: the frame before; the path
        # is `dexmill run --path-overlay`'s (tests/test_api_view.cpp holds it
        # byte for byte); a mark changes the frame and none gives it back.
        with dexmill.Simulation(STOCK, tool="flat:6", grid=(330, 230), checks=("rapid",)) as sim:
            view = sim.view(160, 120)
            view.set_path(4096)
            self.assertEqual(sim.run(RAPID_INTO_STOCK), "done")
            view.render()
            before = view.rgb()
            view.zoom(4, 30, 40)
            view.render()
            self.assertNotEqual(view.rgb(), before)
            view.zoom(-4, 30, 40)
            view.render()
            self.assertEqual(view.rgb(), before)
            self.assertEqual(view.path_info()[1:], (4096, 0))
            self.assertGreater(view.path_info()[0], 3)
            view.set_mark(sim.findings()[0]["at_mm"])
            view.render()
            self.assertNotEqual(view.rgb(), before)
            view.set_mark(None)
            view.render()
            self.assertEqual(view.rgb(), before)
            view.show_path(False)
            view.render()
            self.assertNotEqual(view.rgb(), before)
            with self.assertRaises(dexmill.DexmillError):
                view.zoom(1, 160, 0)

    def test_decorated_antialiased_frame_is_the_clis(self):
        # With the triad and scale bar on and anti-aliased, the frame
        # `dexmill run` draws by default.
        with dexmill.Simulation(STOCK, tool="ball:6", grid=(165, 115)) as sim:
            view = sim.view(160, 120, antialias=True)
            view.set_decorations(True)
            self.assertEqual(sim.run(POCKET), "done")
            view.render()
            rgb = view.rgb()
            binary = os.environ.get("DEXMILL")
            if not binary:
                return
            with tempfile.TemporaryDirectory() as d:
                out = os.path.join(d, "f.ppm")
                subprocess.run([binary, "run", os.path.join(HERE, "run", "pocket.ngc"), "-q", "--stock",
                                "0,0,-10,33,23,0", "--tool", "ball:6", "--grid", "165x115", "--size", "160x120",
                                "--image", out], check=True)
                with open(out, "rb") as f:
                    ppm = f.read()
            self.assertEqual(ppm, b"P6\n160 120\n255\n" + rgb)


    def test_slope_colour_frame_is_the_clis(self):
        # A colour mode (dm_view_set_colour) with its legend, as --color slope draws it.
        with dexmill.Simulation(STOCK, tool="ball:6", grid=(165, 115)) as sim:
            view = sim.view(160, 120, antialias=True)
            view.set_decorations(True)
            view.set_colour("slope")
            with self.assertRaises(dexmill.DexmillError):
                view.set_colour("tool")  # no provenance
            self.assertEqual(sim.run(POCKET), "done")
            view.render()
            rgb = view.rgb()
            binary = os.environ.get("DEXMILL")
            if not binary:
                return
            with tempfile.TemporaryDirectory() as d:
                out = os.path.join(d, "f.ppm")
                subprocess.run([binary, "run", os.path.join(HERE, "run", "pocket.ngc"), "-q", "--stock",
                                "0,0,-10,33,23,0", "--tool", "ball:6", "--grid", "165x115", "--size", "160x120",
                                "--color", "slope", "--image", out], check=True)
                with open(out, "rb") as f:
                    ppm = f.read()
            self.assertEqual(ppm, b"P6\n160 120\n255\n" + rgb)

if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=1).result
    sys.exit(0 if result.wasSuccessful() else 1)
