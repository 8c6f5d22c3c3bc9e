"""dexmill from Python: the C API (display/api/dexmill.h) of libdexmill.so
through ctypes, standard library only.

    import dexmill
    sim = dexmill.Simulation(stock_mm=(0, 0, -10, 33, 23, 0), tool="ball:6", pitch_mm=0.1,
                             checks=("rapid",))
    sim.run(open("part.ngc").read())
    sim.height_mm(15, 7)         # the top there, mm (None: no material)
    sim.findings()               # [{'kind': 'rapid', 'line': 4, ...}]
    sim.errors()                 # [{'line': 2, 'col': 7, 'code': 4, 'message': ...}]
    view = sim.view(320, 240)    # draws as `dexmill run` does
    view.render(); view.pixels   # XRGB8888 rows, top row first

Lengths are mm as numbers (rounded to the nearest nm) or as text (read
exactly, as the CLI reads them). The library: $DEXMILL_LIB, else
libdexmill.so installed beside this file (PREFIX/share/dexmill/python ->
PREFIX/lib) or built beside it (tools/python -> build/), else the system's.
"""

import ctypes
import os

API_VERSION = 1
NM_PER_MM = 1000000

_STATES = {0: "ready", 1: "need_input", 2: "done", 3: "stopped", 4: "io_error"}
_CHECKS = {"rapid": 1, "spindle": 2, "below": 4, "shank": 8, "holder": 16, "plunge": 32, "all": 63}
_STOP_AT = {"gouge": 1, "collision": 2}
_VIEWS = {"iso": 0, "top": 1, "front": 2, "right": 3}
_STOP_REASONS = {0: None, 1: "input_error", 2: "gouge", 3: "collision", 4: "tool", 5: "caller"}
TOOLS_MAX = 16
FIXTURES_MAX = 8
RECTS_MAX = 32
ANTIALIAS = 1  # DM_VIEW_ANTIALIAS


class DexmillError(Exception):
    """A call of the library returned a status other than DM_OK."""

    def __init__(self, status, message):
        super().__init__("%s (status %d)" % (message, status))
        self.status = status


class _Box(ctypes.Structure):
    _fields_ = [("lo_nm", ctypes.c_int64 * 3), ("hi_nm", ctypes.c_int64 * 3)]


class _Triangle(ctypes.Structure):
    _fields_ = [("v_nm", (ctypes.c_int64 * 3) * 3)]


class _Tool(ctypes.Structure):
    _fields_ = [("spec", ctypes.c_char_p), ("shape", ctypes.c_int32), ("tip_angle_mdeg", ctypes.c_int32),
                ("diameter_nm", ctypes.c_int64), ("corner_radius_nm", ctypes.c_int64),
                ("flute_length_nm", ctypes.c_int64), ("stick_out_nm", ctypes.c_int64),
                ("shank_diameter_nm", ctypes.c_int64), ("not_centre_cutting", ctypes.c_int32),
                ("number", ctypes.c_int32), ("length_offset_nm", ctypes.c_int64)]


class _Job(ctypes.Structure):
    _fields_ = [("api_version", ctypes.c_uint32), ("stock", _Box), ("pitch_nm", ctypes.c_int64),
                ("grid_nx", ctypes.c_int32), ("grid_ny", ctypes.c_int32), ("mode", ctypes.c_int32),
                ("units", ctypes.c_int32), ("tool", _Tool), ("tools", _Tool * TOOLS_MAX), ("ntools", ctypes.c_int32),
                ("default_feed_nm_per_min", ctypes.c_int64), ("max_blocks", ctypes.c_uint64),
                ("checks", ctypes.c_uint32), ("has_table", ctypes.c_int32), ("table_z_nm", ctypes.c_int64),
                ("fixtures", _Box * FIXTURES_MAX), ("nfixtures", ctypes.c_int32), ("material", ctypes.c_char_p),
                ("design", ctypes.POINTER(_Triangle)), ("ndesign", ctypes.c_uint32),
                ("tolerance_nm", ctypes.c_int64), ("provenance", ctypes.c_int32), ("stop_at", ctypes.c_uint32),
                ("input_buffer_bytes", ctypes.c_uint32), ("queue_records", ctypes.c_uint32)]


_YIELD = ctypes.CFUNCTYPE(ctypes.c_int32, ctypes.c_void_p)


class _Budget(ctypes.Structure):
    _fields_ = [("moves", ctypes.c_uint64), ("dexel_updates", ctypes.c_uint64), ("lines", ctypes.c_uint32),
                ("yield_", _YIELD), ("yield_ctx", ctypes.c_void_p)]


class _Progress(ctypes.Structure):
    _fields_ = [("state", ctypes.c_int32), ("stop_reason", ctypes.c_int32), ("stop_line", ctypes.c_uint32),
                ("line", ctypes.c_uint32), ("position_nm", ctypes.c_int64 * 3), ("tool", ctypes.c_int32),
                ("failed_tool", ctypes.c_int32), ("feed_nm_per_min", ctypes.c_int64),
                ("machine_time_us", ctypes.c_int64), ("moves", ctypes.c_uint64), ("records", ctypes.c_uint64),
                ("lines_read", ctypes.c_uint32), ("errors", ctypes.c_uint32), ("warnings", ctypes.c_uint32),
                ("units_verdict", ctypes.c_uint32), ("removed_lsb_dexels", ctypes.c_uint64),
                ("removed_um3", ctypes.c_uint64), ("dexel_updates", ctypes.c_uint64)]


class _GridInfo(ctypes.Structure):
    _fields_ = [("nx", ctypes.c_int32), ("ny", ctypes.c_int32), ("x0_nm", ctypes.c_int64), ("y0_nm", ctypes.c_int64),
                ("pitch_nm", ctypes.c_int64), ("z0_nm", ctypes.c_int64), ("lsb_nm", ctypes.c_int64),
                ("stock", _Box)]


class _Column(ctypes.Structure):
    _fields_ = [("i", ctypes.c_int32), ("j", ctypes.c_int32), ("has_material", ctypes.c_int32),
                ("last_tool", ctypes.c_int32), ("top_nm", ctypes.c_int64), ("bottom_nm", ctypes.c_int64),
                ("last_line", ctypes.c_uint32), ("reserved", ctypes.c_uint32)]


class _Finding(ctypes.Structure):
    _fields_ = [("kind", ctypes.c_int32), ("line", ctypes.c_uint32), ("last_line", ctypes.c_uint32),
                ("material", ctypes.c_int32), ("at_nm", ctypes.c_int64 * 3), ("depth_nm", ctypes.c_int64),
                ("value", ctypes.c_int64), ("columns", ctypes.c_uint64)]


class _InputError(ctypes.Structure):
    _fields_ = [("code", ctypes.c_int32), ("line", ctypes.c_uint32), ("col", ctypes.c_uint32),
                ("follow_on", ctypes.c_int32)]


class _Frame(ctypes.Structure):
    _fields_ = [("pixels", ctypes.c_void_p), ("width", ctypes.c_int32), ("height", ctypes.c_int32),
                ("stride_bytes", ctypes.c_int32), ("format", ctypes.c_int32)]


class _Camera(ctypes.Structure):
    _fields_ = [("preset", ctypes.c_int32), ("angles", ctypes.c_int32), ("azimuth_mdeg", ctypes.c_int32),
                ("elevation_mdeg", ctypes.c_int32)]


class _Rect(ctypes.Structure):
    _fields_ = [("x0", ctypes.c_int32), ("y0", ctypes.c_int32), ("x1", ctypes.c_int32), ("y1", ctypes.c_int32)]


class _Colour(ctypes.Structure):
    _fields_ = [("mode", ctypes.c_int32), ("reserved", ctypes.c_int32), ("thin_nm", ctypes.c_int64)]


# dexmill.h DM_COLOUR_*, by the CLI's --color names.
COLOURS = {"plain": 0, "slope": 1, "tool": 2, "material": 3, "thin": 4, "error": 5}

# dexmill.h DM_STRUCT_*: each layout above against the library's.
_LAYOUTS = [(1, _Job), (2, _Tool), (3, _Box), (4, _Triangle), (5, _Budget), (6, _Progress), (7, _GridInfo),
            (8, _Column), (9, _Finding), (10, _InputError), (11, _Frame), (12, _Camera), (13, _Rect),
            (16, _Colour)]


def _find_library():
    if os.environ.get("DEXMILL_LIB"):
        return os.environ["DEXMILL_LIB"]
    here = os.path.dirname(os.path.abspath(__file__))
    for rel in ("../../../lib/libdexmill.so", "../../build/libdexmill.so"):
        path = os.path.normpath(os.path.join(here, rel))
        if os.path.exists(path):
            return path
    return "libdexmill.so"


def _load():
    lib = ctypes.CDLL(_find_library())
    P = ctypes.POINTER
    sim, view = ctypes.c_void_p, ctypes.c_void_p
    st = ctypes.c_int32
    sigs = {
        "dm_status_message": (ctypes.c_char_p, [st]),
        "dm_version": (ctypes.c_uint32, []),
        "dm_struct_bytes": (ctypes.c_size_t, [ctypes.c_int32]),
        "dm_job_init": (st, [P(_Job), ctypes.c_uint32]),
        "dm_required_bytes": (st, [P(_Job), P(ctypes.c_size_t)]),
        "dm_create": (st, [P(_Job), ctypes.c_void_p, ctypes.c_size_t, P(sim)]),
        "dm_destroy": (None, [sim]),
        "dm_feed": (st, [sim, ctypes.c_void_p, ctypes.c_size_t]),
        "dm_input_taken": (ctypes.c_int32, [sim]),
        "dm_feed_line": (st, [sim, ctypes.c_char_p, ctypes.c_size_t]),
        "dm_end_input": (st, [sim]),
        "dm_step": (st, [sim, P(_Budget), P(ctypes.c_int32)]),
        "dm_stop": (st, [sim]),
        "dm_get_progress": (st, [sim, P(_Progress)]),
        "dm_get_grid": (st, [sim, P(_GridInfo)]),
        "dm_column_at": (st, [sim, ctypes.c_int64, ctypes.c_int64, P(_Column)]),
        "dm_finding_count": (ctypes.c_uint32, [sim]),
        "dm_finding_total": (ctypes.c_uint64, [sim]),
        "dm_finding_get": (st, [sim, ctypes.c_uint32, P(_Finding)]),
        "dm_finding_name": (ctypes.c_char_p, [ctypes.c_int32]),
        "dm_error_count": (ctypes.c_uint32, [sim]),
        "dm_error_get": (st, [sim, ctypes.c_uint32, P(_InputError)]),
        "dm_error_message": (ctypes.c_size_t, [sim, ctypes.c_uint32, ctypes.c_char_p, ctypes.c_size_t]),
        "dm_view_bytes": (st, [sim, ctypes.c_int32, ctypes.c_int32, P(ctypes.c_size_t)]),
        "dm_view_create": (st, [sim, P(_Frame), P(_Camera), ctypes.c_void_p, ctypes.c_size_t, P(view)]),
        "dm_view_bytes_flags": (st, [sim, ctypes.c_int32, ctypes.c_int32, ctypes.c_int32, ctypes.c_uint32,
                                     P(ctypes.c_size_t)]),
        "dm_view_create_flags": (st, [sim, P(_Frame), P(_Camera), ctypes.c_uint32, ctypes.c_void_p, ctypes.c_size_t,
                                      P(view)]),
        "dm_render": (st, [view, P(_Rect), ctypes.c_int32, P(ctypes.c_int32)]),
        "dm_view_set_camera": (st, [view, P(_Camera)]),
        "dm_view_set_decorations": (st, [view, ctypes.c_int32]),
        "dm_view_destroy": (None, [view]),
        "dm_warning_count": (ctypes.c_uint32, [sim]),
        "dm_warning_get": (st, [sim, ctypes.c_uint32, P(_InputError)]),
        "dm_warning_message": (ctypes.c_size_t, [sim, ctypes.c_uint32, ctypes.c_char_p, ctypes.c_size_t]),
        "dm_view_zoom": (st, [view, ctypes.c_int32, ctypes.c_int32, ctypes.c_int32]),
        "dm_view_zoom_reset": (st, [view]),
        "dm_path_bytes": (ctypes.c_size_t, [ctypes.c_uint32]),
        "dm_view_set_path": (st, [view, ctypes.c_void_p, ctypes.c_size_t]),
        "dm_view_show_path": (st, [view, ctypes.c_int32]),
        "dm_view_path_info": (st, [view, P(ctypes.c_uint32), P(ctypes.c_uint32), P(ctypes.c_uint64)]),
        "dm_view_set_mark": (st, [view, P(ctypes.c_int64)]),
        "dm_view_colour_bytes": (st, [view, P(_Colour), P(ctypes.c_size_t)]),
        "dm_view_set_colour": (st, [view, P(_Colour), ctypes.c_void_p, ctypes.c_size_t]),
        "dm_material_preset_name": (ctypes.c_char_p, [ctypes.c_int32]),
        "dm_mm_to_nm": (st, [ctypes.c_char_p, ctypes.c_size_t, P(ctypes.c_int64)]),
    }
    for name, (res, args) in sigs.items():
        fn = getattr(lib, name)
        fn.restype, fn.argtypes = res, args
    if lib.dm_version() != API_VERSION:
        raise DexmillError(2, "libdexmill has API version %d, this wrapper %d" % (lib.dm_version(), API_VERSION))
    for which, cls in _LAYOUTS:
        if lib.dm_struct_bytes(which) != ctypes.sizeof(cls):
            raise DexmillError(2, "the layout of %s differs from the library's" % cls.__name__)
    return lib


_lib = _load()


def _check(status):
    if status != 0:
        raise DexmillError(status, _lib.dm_status_message(status).decode())


def nm(mm):
    """mm (a number, or text read exactly) in nm."""
    if isinstance(mm, str):
        out = ctypes.c_int64()
        text = mm.encode()
        _check(_lib.dm_mm_to_nm(text, len(text), ctypes.byref(out)))
        return out.value
    return int(round(mm * NM_PER_MM))


def _block(nbytes):
    """8-byte aligned memory for a handle."""
    return (ctypes.c_uint64 * (nbytes // 8 + 1))()


def _set_box(box, six_mm):
    if len(six_mm) != 6:
        raise ValueError("a box is X0, Y0, Z0, X1, Y1, Z1")
    for k in range(3):
        box.lo_nm[k] = nm(six_mm[k])
        box.hi_nm[k] = nm(six_mm[k + 3])


def _set_tool(t, spec, keep):
    b = spec.encode()
    keep.append(b)
    t.spec = b


def _mm(v_nm):
    return v_nm / NM_PER_MM


class Simulation:
    """One run of a program on a stock (dm_create over memory this object holds)."""

    def __init__(self, stock_mm, tool="flat:6", pitch_mm=None, grid=None, tools=None, units="mm", mode="sweep",
                 checks=(), table_mm=None, fixtures_mm=(), material=None, design_mm=None, tolerance_mm=None,
                 provenance=False, stop_at=(), default_feed_mm_per_min=0):
        job = _Job()
        _check(_lib.dm_job_init(ctypes.byref(job), API_VERSION))
        keep = []  # texts the job points to, alive until dm_create has read them
        _set_box(job.stock, stock_mm)
        if pitch_mm is not None:
            job.pitch_nm = nm(pitch_mm)
        if grid is not None:
            job.grid_nx, job.grid_ny = grid
        _set_tool(job.tool, tool, keep)
        for k, (number, spec, length_mm) in enumerate(tools or []):
            _set_tool(job.tools[k], spec, keep)
            job.tools[k].number = number
            job.tools[k].length_offset_nm = nm(length_mm)
        job.ntools = len(tools or [])
        job.units = {"mm": 0, "inch": 1}[units]
        job.mode = {"sweep": 0, "stamp": 1}[mode]
        for c in checks:
            job.checks |= _CHECKS[c]
        if table_mm is not None:
            job.has_table, job.table_z_nm = 1, nm(table_mm)
        for k, f in enumerate(fixtures_mm):
            _set_box(job.fixtures[k], f)
        job.nfixtures = len(fixtures_mm)
        if material:
            b = material.encode()
            keep.append(b)
            job.material = b
        if design_mm:
            tris = (_Triangle * len(design_mm))()
            for k, tri in enumerate(design_mm):
                for v in range(3):
                    for a in range(3):
                        tris[k].v_nm[v][a] = nm(tri[v][a])
            keep.append(tris)
            job.design = ctypes.cast(tris, ctypes.POINTER(_Triangle))
            job.ndesign = len(design_mm)
        if tolerance_mm is not None:
            job.tolerance_nm = nm(tolerance_mm)
        job.provenance = 1 if provenance else 0
        for s in stop_at:
            job.stop_at |= _STOP_AT[s]
        job.default_feed_nm_per_min = nm(default_feed_mm_per_min)
        n = ctypes.c_size_t()
        _check(_lib.dm_required_bytes(ctypes.byref(job), ctypes.byref(n)))
        self._mem = _block(n.value)
        self._sim = ctypes.c_void_p()
        _check(_lib.dm_create(ctypes.byref(job), self._mem, n.value, ctypes.byref(self._sim)))
        self._piece = None  # the text lent to the simulation until it is taken
        self._views = []

    def close(self):
        """Ends the simulation (its views stop drawing)."""
        if self._sim:
            _lib.dm_destroy(self._sim)
            self._sim = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def feed(self, text):
        """Lends a piece of program text (str or bytes); the last piece must be taken."""
        data = text.encode() if isinstance(text, str) else bytes(text)
        buf = ctypes.create_string_buffer(data, len(data))
        _check(_lib.dm_feed(self._sim, buf, len(data)))
        self._piece = buf

    def feed_line(self, line):
        data = line.encode() if isinstance(line, str) else bytes(line)
        _check(_lib.dm_feed_line(self._sim, data, len(data)))

    def input_taken(self):
        return _lib.dm_input_taken(self._sim) == 1

    def end_input(self):
        _check(_lib.dm_end_input(self._sim))

    def step(self, moves=0, lines=0, dexel_updates=0):
        """One slice; its state: 'ready', 'need_input', 'done', 'stopped' or 'io_error'."""
        b = _Budget(moves=moves, lines=lines, dexel_updates=dexel_updates)
        state = ctypes.c_int32()
        _check(_lib.dm_step(self._sim, ctypes.byref(b), ctypes.byref(state)))
        return _STATES[state.value]

    def run(self, text, piece=4096, moves=0, each=None):
        """The whole program, fed in pieces of `piece` bytes, `moves` moves a step
        (0: no limit), each(self) after every slice; the final state."""
        data = text.encode() if isinstance(text, str) else bytes(text)
        at = 0
        while True:
            state = self.step(moves=moves)
            if state == "need_input":
                if at < len(data):
                    self.feed(data[at:at + piece])
                    at += piece
                else:
                    self.end_input()
            elif state == "ready":
                if each:
                    each(self)
            else:
                return state

    def stop(self):
        _check(_lib.dm_stop(self._sim))

    def progress(self):
        p = _Progress()
        _check(_lib.dm_get_progress(self._sim, ctypes.byref(p)))
        return {"state": _STATES[p.state], "stop_reason": _STOP_REASONS.get(p.stop_reason), "stop_line": p.stop_line,
                "line": p.line, "position_mm": tuple(_mm(v) for v in p.position_nm), "tool": p.tool,
                "moves": p.moves, "lines_read": p.lines_read, "errors": p.errors, "warnings": p.warnings,
                "machine_time_s": p.machine_time_us / 1e6, "removed_mm3": p.removed_um3 / 1e9,
                "dexel_updates": p.dexel_updates}

    def grid(self):
        g = _GridInfo()
        _check(_lib.dm_get_grid(self._sim, ctypes.byref(g)))
        return {"nx": g.nx, "ny": g.ny, "x0_mm": _mm(g.x0_nm), "y0_mm": _mm(g.y0_nm), "pitch_mm": _mm(g.pitch_nm),
                "z0_mm": _mm(g.z0_nm), "lsb_mm": _mm(g.lsb_nm)}

    def column(self, x_mm, y_mm):
        """The column nearest to (x, y), or None outside the grid."""
        c = _Column()
        status = _lib.dm_column_at(self._sim, nm(x_mm), nm(y_mm), ctypes.byref(c))
        if status == 15:  # DM_E_OUTSIDE
            return None
        _check(status)
        return {"i": c.i, "j": c.j, "material": bool(c.has_material), "top_mm": _mm(c.top_nm),
                "bottom_mm": _mm(c.bottom_nm), "last_tool": c.last_tool, "last_line": c.last_line}

    def height_mm(self, x_mm, y_mm):
        """The top at (x, y) in mm; None where there is no material."""
        c = self.column(x_mm, y_mm)
        return c["top_mm"] if c and c["material"] else None

    def findings(self):
        out = []
        for k in range(_lib.dm_finding_count(self._sim)):
            f = _Finding()
            _check(_lib.dm_finding_get(self._sim, k, ctypes.byref(f)))
            out.append({"kind": _lib.dm_finding_name(f.kind).decode(), "line": f.line, "last_line": f.last_line,
                        "at_mm": tuple(_mm(v) for v in f.at_nm), "depth_mm": _mm(f.depth_nm), "value": f.value,
                        "material": f.material, "columns": f.columns})
        return out

    def findings_total(self):
        return _lib.dm_finding_total(self._sim)

    def errors(self):
        return self._diags(_lib.dm_error_count, _lib.dm_error_get, _lib.dm_error_message)

    def warnings(self):
        """The first 16 warnings, as errors() (the text `dexmill check` prints)."""
        return self._diags(_lib.dm_warning_count, _lib.dm_warning_get, _lib.dm_warning_message)

    def _diags(self, count, get, message):
        out = []
        for k in range(min(count(self._sim), 16)):
            e = _InputError()
            if get(self._sim, k, ctypes.byref(e)) != 0:
                break
            msg = ctypes.create_string_buffer(512)
            message(self._sim, k, msg, len(msg))
            out.append({"code": e.code, "line": e.line, "col": e.col, "follow_on": bool(e.follow_on),
                        "message": msg.value.decode(errors="replace")})
        return out

    def view(self, width, height, view="iso", azimuth_deg=None, elevation_deg=None, antialias=False):
        v = View(self, width, height, view, azimuth_deg, elevation_deg, antialias)
        self._views.append(v)
        return v


def _camera(view, azimuth_deg, elevation_deg):
    c = _Camera(preset=_VIEWS[view])
    if azimuth_deg is not None or elevation_deg is not None:
        c.angles = 1
        c.azimuth_mdeg = int(round((azimuth_deg or 0) * 1000))
        c.elevation_mdeg = int(round((elevation_deg or 0) * 1000))
    return c


class View:
    """The simulation drawn into an XRGB8888 frame this object holds."""

    def __init__(self, sim, width, height, view="iso", azimuth_deg=None, elevation_deg=None, antialias=False):
        """antialias: edges 2x2 supersampled (DM_VIEW_ANTIALIAS), as `dexmill run`'s images."""
        self.width, self.height = width, height
        self._sim = sim
        self._pixels = (ctypes.c_uint32 * (width * height))()
        flags = ANTIALIAS if antialias else 0
        n = ctypes.c_size_t()
        _check(_lib.dm_view_bytes_flags(sim._sim, width, height, 0, flags, ctypes.byref(n)))
        self._mem = _block(n.value)
        frame = _Frame(ctypes.cast(self._pixels, ctypes.c_void_p), width, height, width * 4, 0)
        cam = _camera(view, azimuth_deg, elevation_deg)
        self._view = ctypes.c_void_p()
        _check(_lib.dm_view_create_flags(sim._sim, ctypes.byref(frame), ctypes.byref(cam), flags, self._mem, n.value,
                                         ctypes.byref(self._view)))

    def render(self):
        """Draws what changed; the rectangles (x0, y0, x1, y1) that did."""
        rects = (_Rect * RECTS_MAX)()
        n = ctypes.c_int32()
        _check(_lib.dm_render(self._view, rects, RECTS_MAX, ctypes.byref(n)))
        return [(r.x0, r.y0, r.x1, r.y1) for r in rects[:n.value]]

    def set_camera(self, view="iso", azimuth_deg=None, elevation_deg=None):
        cam = _camera(view, azimuth_deg, elevation_deg)
        _check(_lib.dm_view_set_camera(self._view, ctypes.byref(cam)))

    def set_decorations(self, on=True):
        """The axis triad and scale bar, as `dexmill run` draws them (off at first)."""
        _check(_lib.dm_view_set_decorations(self._view, 1 if on else 0))

    def zoom(self, steps, x, y):
        """steps (> 0 in, 9/10 of the height each) about pixel (x, y), which stays put."""
        _check(_lib.dm_view_zoom(self._view, steps, x, y))

    def zoom_reset(self):
        _check(_lib.dm_view_zoom_reset(self._view))

    def set_path(self, segments):
        """The toolpath (`--path-overlay`) collected from now on, room for `segments` pieces (0: none)."""
        n = _lib.dm_path_bytes(segments)
        self._path_mem = _block(n) if segments else None
        _check(_lib.dm_view_set_path(self._view, ctypes.cast(self._path_mem, ctypes.c_void_p) if segments else None, n))

    def show_path(self, on=True):
        _check(_lib.dm_view_show_path(self._view, 1 if on else 0))

    def path_info(self):
        """(pieces held, room, pieces dropped once full)."""
        n, cap, dropped = ctypes.c_uint32(), ctypes.c_uint32(), ctypes.c_uint64()
        _check(_lib.dm_view_path_info(self._view, ctypes.byref(n), ctypes.byref(cap), ctypes.byref(dropped)))
        return n.value, cap.value, dropped.value

    def set_mark(self, at_mm=None):
        """A marker at (x, y, z) mm (a finding's at_mm); None: none."""
        at = (ctypes.c_int64 * 3)(*(nm(v) for v in at_mm)) if at_mm is not None else None
        _check(_lib.dm_view_set_mark(self._view, at))

    def set_colour(self, mode="plain", thin_mm=0):
        """A colour mode by the CLI's --color name, its legend drawn (tool needs provenance, material
        a material, error a design); thin_mm the --thin limit (0: 1 mm)."""
        c = _Colour(COLOURS[mode], 0, nm(thin_mm))
        n = ctypes.c_size_t()
        _check(_lib.dm_view_colour_bytes(self._view, ctypes.byref(c), ctypes.byref(n)))
        self._colour_mem = _block(n.value) if n.value else None
        _check(_lib.dm_view_set_colour(self._view, ctypes.byref(c), self._colour_mem, n.value))

    @property
    def pixels(self):
        """The frame: 0xFFRRGGBB words, rows top first, as bytes (native order)."""
        return bytes(self._pixels)

    def rgb(self):
        """The frame as R, G, B bytes, rows top first (a PPM's body)."""
        out = bytearray(self.width * self.height * 3)
        for k, v in enumerate(self._pixels):
            out[3 * k:3 * k + 3] = bytes(((v >> 16) & 255, (v >> 8) & 255, v & 255))
        return bytes(out)
