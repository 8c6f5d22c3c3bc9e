/* dexmill.h - the embedding API of dexmill: a 3-axis milling simulation
 * (a dexel height grid cut by the program's moves, exactly and integer
 * only) and its picture, for C and C++ programs, a controller's firmware,
 * or Python through ctypes (tools/python/dexmill.py).
 *
 * C99, usable from C++ (extern "C"). Every value is a fixed-size integer:
 * lengths in nanometres (1 mm = DM_NM_PER_MM), angles in millidegrees,
 * feeds in nm per minute; no floating point, no exceptions, no allocation:
 * each handle lives in memory the caller gives (8-byte aligned) and sizes
 * with a query first. Errors are status codes (dm_status_message), never
 * aborts; a null or destroyed handle is DM_E_ARGUMENT.
 *
 * A run:
 *
 *   dm_job job;
 *   dm_job_init(&job, DEXMILL_API_VERSION);
 *   job.stock.lo_nm[0] = 0; ... job.stock.hi_nm[2] = 0;   (the block, machine coordinates)
 *   job.tool.spec = "ball:6";                         (the CLI's --tool text)
 *   size_t n; dm_required_bytes(&job, &n);
 *   dm_sim* sim; dm_create(&job, malloc(n), n, &sim);  (any 8-byte aligned memory)
 *
 *   for (;;) {                                        (the caller's loop, idle task, timer)
 *     int32_t state;
 *     dm_step(sim, &budget, &state);                  (returns at a record boundary)
 *     if (state == DM_NEED_INPUT) { piece of the file read? dm_feed(sim, buf, got) : dm_end_input(sim); }
 *     else if (state != DM_READY) break;              (DM_DONE, DM_STOPPED, DM_IO_ERROR)
 *     (between steps: queries, dm_render)
 *   }
 *   dm_destroy(sim);
 *
 * Text fed with dm_feed is lent, as zlib's next_in is: it must stay where it
 * is until dm_input_taken says the simulation has read it all (then feed the
 * next piece). dm_feed_line copies one line instead. The first lines come
 * once the reader's buffer is full or the input ends: what is text is
 * decided on the program's first bytes, as for a file.
 *
 * The picture: dm_view_bytes for a frame size, dm_view_create over the
 * caller's pixels (XRGB8888 or RGB565, any stride), then dm_render draws
 * what changed since the last render (the whole frame the first time) and
 * says which rectangles to present. Views see every change of the grid;
 * several may watch one simulation.
 *
 * After dm_create nothing allocates and nothing grows.
 */
#ifndef DEXMILL_H
#define DEXMILL_H

#include <stddef.h>
#include <stdint.h>

/* The API this header describes. A program compiled against another
 * version is refused by dm_job_init (DM_E_VERSION). */
#define DEXMILL_API_VERSION 1

#if defined(__GNUC__) || defined(__clang__)
#define DM_API __attribute__((visibility("default")))
#else
#define DM_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

#define DM_NM_PER_MM 1000000

/* ---- status codes (stable numbers) ---- */
typedef int32_t dm_status;
enum {
  DM_OK = 0,
  DM_E_ARGUMENT = 1,    /* a null pointer or handle, a value outside its range */
  DM_E_VERSION = 2,     /* the job was not set up by dm_job_init of this API version */
  DM_E_MEMORY = 3,      /* memory null, not 8-byte aligned, or smaller than its query said */
  DM_E_STOCK = 4,       /* the stock box is empty on an axis or lies beyond +-1 km */
  DM_E_GRID = 5,        /* the grid: under 4 x 4 dexels, over 65535 a side or 64 M dexels, or out of range */
  DM_E_TOOL_SPEC = 6,   /* a tool's spec text does not parse (core/tool/spec.h) */
  DM_E_TOOL = 7,        /* a tool is out of range, or cannot cut this grid in this mode */
  DM_E_TOOL_NUMBER = 8, /* a library tool's number is negative or used twice, or too many tools */
  DM_E_FIXTURES = 9,    /* too many fixtures, or they hold no column of the stock's lattice */
  DM_E_MATERIAL = 10,   /* not a material preset's name */
  DM_E_DESIGN = 11,     /* the design's triangles lie beyond 1.07 m of the grid's corner, or none over the stock */
  DM_E_STATE = 12,      /* not now: input after dm_end_input, a view of a destroyed simulation */
  DM_E_BUSY = 13,       /* the text fed before is not taken yet (dm_input_taken) */
  DM_E_LINE = 14,       /* dm_feed_line: longer than DM_LINE_MAX */
  DM_E_OUTSIDE = 15,    /* a point outside the grid */
  DM_E_FRAME = 16,      /* a frame the renderer cannot draw into (size, stride, format) */
  DM_E_INDEX = 17,      /* past the end of a list */
  DM_E_IO = 18,         /* a file could not be written (dexmill_io.h) */
  DM_E_TOOL_TABLE = 19, /* a tool table's line does not read (dm_tool_table_parse) */
  DM_E_COLOUR = 20      /* a colour mode the job cannot draw: tool without provenance, material without one, error without a design */
};
/* A sentence for a status; never NULL. */
DM_API const char* dm_status_message(dm_status s);
/* The API version of the library (DEXMILL_API_VERSION when built). */
DM_API uint32_t dm_version(void);

/* ---- the job ---- */
#define DM_TOOLS_MAX 16
#define DM_FIXTURES_MAX 8
#define DM_LINE_MAX 256
#define DM_INPUT_MIN_BYTES 1024

enum { DM_UNITS_MM = 0, DM_UNITS_INCH = 1 };
enum { DM_MODE_SWEEP = 0, DM_MODE_STAMP = 1 };  /* exact swept envelope, or the paper's instances */
enum { DM_TOOL_FLAT = 0, DM_TOOL_BALL = 1, DM_TOOL_BULL = 2, DM_TOOL_VBIT = 3 };
enum {  /* dm_job.checks: the safety checks (the CLI's --check) */
  DM_CHECK_RAPID = 1,    /* a rapid that removes material */
  DM_CHECK_SPINDLE = 2,  /* cutting with the spindle stopped */
  DM_CHECK_BELOW = 4,    /* the tip below the stock's bottom */
  DM_CHECK_SHANK = 8,    /* the shank above the flutes in material */
  DM_CHECK_HOLDER = 16,  /* the holder in material */
  DM_CHECK_PLUNGE = 32,  /* a tool that is not centre cutting plunging straight down */
  DM_CHECK_ALL = 63
};
enum { DM_STOP_AT_GOUGE = 1, DM_STOP_AT_COLLISION = 2 };  /* dm_job.stop_at */

typedef struct dm_box {
  int64_t lo_nm[3]; /* x, y, z */
  int64_t hi_nm[3];
} dm_box;

typedef struct dm_triangle {
  int64_t v_nm[3][3]; /* three vertices x, y, z, machine coordinates */
} dm_triangle;

/* A tool: its spec text, or (spec NULL) the fields; DM_E_TOOL outside the
 * ranges of core/tool/tool.h (1 um to 1 m across, a V-bit's angle 1000 to
 * 179999 millidegrees, stick-out up to 10 m). */
typedef struct dm_tool {
  const char* spec;           /* "ball:6", "bull:10:1.5,len=25,holder=20x10", ... (read by dm_required_bytes and dm_create only) */
  int32_t shape;              /* DM_TOOL_* */
  int32_t tip_angle_mdeg;     /* V-bit: the included angle, 1000..179999 */
  int64_t diameter_nm;
  int64_t corner_radius_nm;   /* bull nose */
  int64_t flute_length_nm;    /* 0: cuts along its whole length */
  int64_t stick_out_nm;       /* tip to holder face; 0: max(flutes, profile height, 2 D, 30 mm) */
  int64_t shank_diameter_nm;  /* 0: the cutting diameter */
  int32_t not_centre_cutting; /* non-zero: must not plunge straight down */
  int32_t number;             /* library tools: the T number (0 or more) */
  int64_t length_offset_nm;   /* library tools: the length G43 H applies */
} dm_tool;

typedef struct dm_job {
  uint32_t api_version;        /* set by dm_job_init */
  dm_box stock;                /* the block, machine coordinates */
  /* The grid: pitch_nm, or (pitch 0) grid_nx x grid_ny at most (the finest
   * pitch that fits, keeping the stock's shape), or (all 0) a 32nd of the
   * smallest tool, 256 to 1024 dexels across the stock's longer side. */
  int64_t pitch_nm;
  int32_t grid_nx, grid_ny;
  int32_t mode;                /* DM_MODE_* */
  int32_t units;               /* DM_UNITS_*: of programs with no G20/G21 */
  dm_tool tool;                /* in the spindle before any M6 */
  dm_tool tools[DM_TOOLS_MAX]; /* what T/M6 load by number; none: every T is `tool` */
  int32_t ntools;
  int64_t default_feed_nm_per_min; /* for feed moves with none in force (0: an error) */
  uint64_t max_blocks;         /* 0: the default (10 M blocks, o-word loops included) */
  uint32_t checks;             /* DM_CHECK_*; a tool's flute length, holder or not centre cutting adds its check */
  int32_t has_table;           /* non-zero: the tip below table_z_nm is a finding */
  int64_t table_z_nm;
  dm_box fixtures[DM_FIXTURES_MAX]; /* boxes the tool and holder must never enter, drawn in views */
  int32_t nfixtures;
  const char* material;        /* a preset ("wood", "aluminium", "wood-on-aluminium", ...): its feed,
                                  spindle and coolant rules are checked; NULL: none */
  const dm_triangle* design;   /* the part the cut must not go into (read by dm_create only); NULL: none */
  uint32_t ndesign;
  int64_t tolerance_nm;        /* deeper than this under the design is a gouge (default 0.05 mm) */
  int32_t provenance;          /* non-zero: which tool and line last cut each column (dm_column) */
  uint32_t stop_at;            /* DM_STOP_AT_*: stop at the end of a line that gouged or collided */
  uint32_t input_buffer_bytes; /* the reader's buffer for fed text (0: 64 KiB; at least DM_INPUT_MIN_BYTES) */
  uint32_t queue_records;      /* records of one line held when a step's budget ends in it (0: 64) */
} dm_job;

/* Every field to its default (stock and tool empty). DM_E_VERSION when
 * api_version is not the library's. */
DM_API dm_status dm_job_init(dm_job* job, uint32_t api_version);
/* An STL file's facets (its bytes in memory, binary or ASCII, mm) as
 * triangles for dm_job.design: *count of them, written to out[0, max)
 * (out NULL: counted only; more than max: DM_E_INDEX, the first max
 * written). DM_E_DESIGN when the bytes are not an STL mesh (a vertex not a
 * number or beyond 10 m, a facet cut short, none at all). */
DM_API dm_status dm_design_from_stl(const void* bytes, size_t n, dm_triangle* out, uint32_t max, uint32_t* count);
/* The material presets dm_job.material names, index 0 on ("two-layer",
 * "wood", ...; the CLI's --material PRESET); NULL past the last. */
DM_API const char* dm_material_preset_name(int32_t index);

/* ---- the simulation ---- */
typedef struct dm_sim dm_sim;

/* Bytes a simulation of the job needs (the grid, the interpreter, the
 * observers the job asks for). Uses about 4 KB of stack. */
DM_API dm_status dm_required_bytes(const dm_job* job, size_t* bytes);
/* Sets the simulation up in mem (8-byte aligned, at least
 * dm_required_bytes): the stock filled, nothing read yet. Nothing the job
 * points to is needed afterwards. */
DM_API dm_status dm_create(const dm_job* job, void* mem, size_t bytes, dm_sim** out);
/* Ends it (the memory is the caller's again); views still watching it
 * answer DM_E_STATE from then on. NULL is ignored. */
DM_API void dm_destroy(dm_sim* sim);

/* Program text in pieces: text[0, n) is lent until dm_input_taken. */
DM_API dm_status dm_feed(dm_sim* sim, const char* text, size_t n);
/* 1 when every byte fed has been read (feed the next piece), else 0. */
DM_API int32_t dm_input_taken(const dm_sim* sim);
/* One line (without its line end; at most DM_LINE_MAX bytes), copied. */
DM_API dm_status dm_feed_line(dm_sim* sim, const char* line, size_t n);
/* The program has no more text. */
DM_API dm_status dm_end_input(dm_sim* sim);

/* What a step may spend: each count is a most (0: no limit); the first
 * reached ends the step, at a record boundary. A line that makes more
 * records than the queue holds (a deep peck cycle) is cut past the budget. */
typedef struct dm_budget {
  uint64_t moves;           /* motion records (G0, G1, arcs) */
  uint64_t dexel_updates;   /* the cut's work */
  uint32_t lines;           /* program lines read */
  /* Asked after every record: non-zero ends the step (a deadline on the
   * caller's clock). NULL: never. */
  int32_t (*yield)(void* ctx);
  void* yield_ctx;
} dm_budget;

enum {
  DM_READY = 0,       /* more to do: step again */
  DM_NEED_INPUT = 1,  /* the text fed is used up: dm_feed more, or dm_end_input */
  DM_DONE = 2,        /* the program ran to its end */
  DM_STOPPED = 3,     /* stopped early (dm_progress.stop_reason) */
  DM_IO_ERROR = 4     /* the input could not be read */
};
/* Reads and cuts until the budget (NULL: none) is spent or input is
 * needed; *state one of the above. */
DM_API dm_status dm_step(dm_sim* sim, const dm_budget* budget, int32_t* state);
/* Stops the run here (DM_STOPPED, reason DM_STOPPED_BY_CALLER). */
DM_API dm_status dm_stop(dm_sim* sim);

/* ---- what it knows ---- */
enum {  /* dm_progress.stop_reason */
  DM_STOPPED_NOT = 0,
  DM_STOPPED_INPUT_ERROR = 1, /* the program's first input error */
  DM_STOPPED_GOUGE = 2,
  DM_STOPPED_COLLISION = 3,
  DM_STOPPED_TOOL = 4,        /* a T the library lacks, or one too large for the memory sized */
  DM_STOPPED_BY_CALLER = 5
};
enum {  /* dm_progress.units_verdict (core/interp/units_guess.h) */
  DM_UNITS_VERDICT_SET = 0,       /* the program set them (G20/G21) before its first move, or made none */
                                  /* (1: units a caller marked as chosen; this API has no such mark) */
  DM_UNITS_VERDICT_DEFAULT = 2,   /* it did not: read in dm_job.units (a warning at that move) */
  DM_UNITS_VERDICT_LOOK_INCH = 3  /* it never did, dm_job.units is mm, and its numbers look like inches (warned) */
};
typedef struct dm_progress {
  int32_t state;              /* the last step's DM_READY ... */
  int32_t stop_reason;        /* DM_STOPPED_* */
  uint32_t stop_line;
  uint32_t line;              /* the program line of the last record cut */
  int64_t position_nm[3];     /* the tool tip now, machine coordinates */
  int32_t tool;               /* the T number in the spindle (0 before any M6) */
  int32_t failed_tool;        /* DM_STOPPED_TOOL: the T number */
  int64_t feed_nm_per_min;    /* the last feed move's */
  int64_t machine_time_us;    /* estimated machine time so far */
  uint64_t moves;             /* motion records cut */
  uint64_t records;
  uint32_t lines_read;
  uint32_t errors;            /* input errors (dm_input_error) */
  uint32_t warnings;
  uint32_t units_verdict;     /* DM_UNITS_VERDICT_*: the program's units (final once it is read to its end) */
  uint64_t removed_lsb_dexels; /* material removed, exactly: times lsb_nm * pitch_nm^2 is nm^3 */
  uint64_t removed_um3;        /* the same in cubic micrometres, rounded */
  uint64_t dexel_updates;      /* the cut's work so far */
} dm_progress;
DM_API dm_status dm_get_progress(const dm_sim* sim, dm_progress* out);

typedef struct dm_grid_info {
  int32_t nx, ny;             /* dexels; a ring of empty ones surrounds the stock */
  int64_t x0_nm, y0_nm;       /* machine x, y of dexel (0, 0)'s axis */
  int64_t pitch_nm;
  int64_t z0_nm;              /* machine z of height 0 (the stock's bottom) */
  int64_t lsb_nm;             /* one height step */
  dm_box stock;               /* the stock as the grid holds it (rounded up to whole pitches) */
} dm_grid_info;
DM_API dm_status dm_get_grid(const dm_sim* sim, dm_grid_info* out);

/* The dexel column whose axis is nearest to (x, y). */
typedef struct dm_column {
  int32_t i, j;
  int32_t has_material;       /* 0: cut through, or outside the stock */
  int32_t last_tool;          /* job.provenance: the T number that last cut it (-1: the job's tool before any M6; -2: uncut) */
  int64_t top_nm, bottom_nm;  /* machine z */
  uint32_t last_line;         /* job.provenance: the line that last lowered it (0: none) */
  uint32_t reserved;
} dm_column;
DM_API dm_status dm_column_at(const dm_sim* sim, int64_t x_nm, int64_t y_nm, dm_column* out);
/* The top (machine z) there; a column without material has none:
 * DM_E_OUTSIDE, as outside the grid. */
DM_API dm_status dm_height_nm(const dm_sim* sim, int64_t x_nm, int64_t y_nm, int64_t* top_nm);

/* Findings so far: gouges (job.design), then safety findings (checks,
 * fixtures, table), then process rule breaks (job.material); each list
 * keeps its first 64 and counts the rest. */
enum {
  DM_FIND_GOUGE = 1,
  DM_FIND_RAPID = 2,          /* a rapid removed material */
  DM_FIND_SPINDLE = 3,        /* cut with the spindle stopped */
  DM_FIND_BELOW = 4,          /* the tip went below the stock */
  DM_FIND_TABLE = 5,          /* the tip went below the table */
  DM_FIND_SHANK = 6,
  DM_FIND_HOLDER = 7,
  DM_FIND_FIXTURE = 8,
  DM_FIND_PLUNGE = 9,
  DM_FIND_FEED = 10,          /* feed over the material's limit */
  DM_FIND_SPEED = 11,         /* spindle speed outside the material's range */
  DM_FIND_COOLANT = 12        /* coolant the material forbids, or none where it needs it */
};
typedef struct dm_finding {
  int32_t kind;               /* DM_FIND_* */
  uint32_t line;              /* the program line */
  uint32_t last_line;         /* a stretch's last line (spindle, shank, holder), else line */
  int32_t material;           /* rule breaks: the material's index in the preset, else -1 */
  int64_t at_nm[3];           /* where: the deepest column (gouges: on the design's surface) */
  int64_t depth_nm;           /* how deep: under the design, under the limit, into material */
  int64_t value;              /* rule breaks: the feed (nm/min), speed (rpm) or coolant bits (1 mist, 2 flood) */
  uint64_t columns;           /* dexel columns involved */
} dm_finding;
/* Findings kept (index 0 .. count - 1) and found in all. */
DM_API uint32_t dm_finding_count(const dm_sim* sim);
DM_API uint64_t dm_finding_total(const dm_sim* sim);
DM_API dm_status dm_finding_get(const dm_sim* sim, uint32_t index, dm_finding* out);
/* "gouge", "rapid", "spindle_stopped", ...; never NULL. */
DM_API const char* dm_finding_name(int32_t kind);

/* Input errors (the first 16 kept; dm_progress.errors counts all). */
typedef struct dm_input_error {
  int32_t code;               /* stable G-code error number */
  uint32_t line;              /* 1-based */
  uint32_t col;               /* 1-based byte column */
  int32_t follow_on;          /* non-zero: may only follow from an earlier error */
} dm_input_error;
DM_API uint32_t dm_error_count(const dm_sim* sim);
DM_API dm_status dm_error_get(const dm_sim* sim, uint32_t index, dm_input_error* out);
/* Its message, NUL terminated, truncated to n - 1 bytes; the length written
 * (0 for a bad index). */
DM_API size_t dm_error_message(const dm_sim* sim, uint32_t index, char* buf, size_t n);

/* Warnings (the first 16 kept; dm_warning_count and dm_progress.warnings
 * count all), as `dexmill check` prints them (FILE:LINE:COL: warning: ...):
 * the fields of an input error (code, line, col) and the message, as
 * dm_error_get and dm_error_message. */
DM_API uint32_t dm_warning_count(const dm_sim* sim);
DM_API dm_status dm_warning_get(const dm_sim* sim, uint32_t index, dm_input_error* out);
DM_API size_t dm_warning_message(const dm_sim* sim, uint32_t index, char* buf, size_t n);

/* ---- the picture ---- */
typedef struct dm_view dm_view;
enum { DM_XRGB8888 = 0, DM_RGB565 = 1 };
enum { DM_VIEW_ISO = 0, DM_VIEW_TOP = 1, DM_VIEW_FRONT = 2, DM_VIEW_RIGHT = 3 };
#define DM_RECTS_MAX 32
#define DM_FRAME_MAX_SIDE 4096

typedef struct dm_frame {
  void* pixels;               /* row 0 at the top */
  int32_t width, height;      /* 1 .. DM_FRAME_MAX_SIDE */
  int32_t stride_bytes;       /* bytes from one row to the next */
  int32_t format;             /* DM_XRGB8888 (0xFFRRGGBB) or DM_RGB565 */
} dm_frame;

/* A preset, or (angles non-zero) azimuth and elevation; fitted to the stock
 * and fixtures. */
typedef struct dm_camera {
  int32_t preset;             /* DM_VIEW_* */
  int32_t angles;
  int32_t azimuth_mdeg;       /* the eye around +z from +x */
  int32_t elevation_mdeg;     /* the eye above the xy plane, -90000 .. 90000 */
} dm_camera;

typedef struct dm_rect {
  int32_t x0, y0, x1, y1;     /* [x0, x1) x [y0, y1) */
} dm_rect;

/* Bytes of a view of this simulation at this frame size. */
DM_API dm_status dm_view_bytes(const dm_sim* sim, int32_t width, int32_t height, size_t* bytes);
/* A view into the caller's frame (camera NULL: iso), in mem of
 * dm_view_bytes. The stock's size is taken now: create views before the
 * first step to frame the whole block. */
DM_API dm_status dm_view_create(dm_sim* sim, const dm_frame* frame, const dm_camera* camera, void* mem, size_t bytes,
                                dm_view** out);
/* Views with options, flags of DM_VIEW_* (0: as dm_view_create).
 * DM_VIEW_ANTIALIAS: edges anti-aliased as `dexmill run` draws its images,
 * by 2x2 supersampling: the scene drawn at twice the frame's width and
 * height in the view's memory and averaged into the frame, the marks and
 * decorations drawn over it at its own size. About 5x the memory of an
 * aliased view (4x its scratch, and the doubled frame in this format) and
 * 4x the pixels per render; the frame at most DM_FRAME_MAX_SIDE / 2 a side (else DM_E_FRAME).
 * Unknown flags: DM_E_ARGUMENT. */
#define DM_VIEW_ANTIALIAS 1u
DM_API dm_status dm_view_bytes_flags(const dm_sim* sim, int32_t width, int32_t height, int32_t format, uint32_t flags,
                                     size_t* bytes);
DM_API dm_status dm_view_create_flags(dm_sim* sim, const dm_frame* frame, const dm_camera* camera, uint32_t flags,
                                      void* mem, size_t bytes, dm_view** out);
/* Draws what changed since the last render (all of it the first time and
 * after a camera change): the tool where it is now. rects[0, *nrects)
 * (rects may be NULL; at most max_rects, the rest merged into the last)
 * cover every pixel that changed. */
DM_API dm_status dm_render(dm_view* view, dm_rect* rects, int32_t max_rects, int32_t* nrects);
DM_API dm_status dm_view_set_camera(dm_view* view, const dm_camera* camera);
/* on non-zero: an axis triad and a 1-2-5 mm scale bar in the bottom-left
 * corner, as `dexmill run` draws them (off after dm_view_create; a panel
 * may keep them off). The camera is framed again, clear of them. */
DM_API dm_status dm_view_set_decorations(dm_view* view, int32_t on);
/* The toolpath over the picture, as `dexmill run --path-overlay` draws it
 * (rapids dashed, feeds solid, arcs as chords of 0.01 mm sagitta): the moves
 * cut from now on, collected as the simulation cuts them into mem (8-byte
 * aligned; NULL: no path), dm_path_bytes(segments) for room for that many
 * pieces (a straight move is one, an arc its chords). When it is full the
 * rest is dropped and counted (dm_view_path_info), never written past it.
 * Set it before the first step for the whole path; shown until
 * dm_view_show_path(view, 0). */
DM_API size_t dm_path_bytes(uint32_t segments);
DM_API dm_status dm_view_set_path(dm_view* view, void* mem, size_t bytes);
DM_API dm_status dm_view_show_path(dm_view* view, int32_t on);
/* The pieces held, the room for them, and the pieces dropped once full. */
DM_API dm_status dm_view_path_info(const dm_view* view, uint32_t* segments, uint32_t* capacity, uint64_t* dropped);
/* A marker (light blue, as the live window marks a click) at the machine
 * point at_nm[0..2] (x, y, z; a finding's at_nm) over every frame, over the
 * marks every view draws as `dexmill run` draws them (the gouges in red, the
 * safety findings in magenta, where the cut stopped: display/api/run_marks.h);
 * NULL: none. The next render draws the whole frame. */
DM_API dm_status dm_view_set_mark(dm_view* view, const int64_t* at_nm);
/* Zooms `steps` steps (> 0 towards the scene; each shows 9/10 of the
 * height the last showed) about the frame's pixel (x_px, y_px): the point
 * drawn there stays there. The zoom stays through dm_view_set_camera (an
 * orbit keeps it) until dm_view_zoom_reset; zooming back out about the same
 * pixel gives the frame before, byte for byte. Stops at 60 steps in and 20
 * out (DM_OK, nothing changes past them). The live window's wheel is the
 * same code (display/view/view_zoom.h). DM_E_ARGUMENT: a pixel outside the
 * frame, |steps| over 1000. */
DM_API dm_status dm_view_zoom(dm_view* view, int32_t steps, int32_t x_px, int32_t y_px);
/* No zoom: the camera as dm_view_set_camera (or dm_view_create) gave it. */
DM_API dm_status dm_view_zoom_reset(dm_view* view);

/* Colour modes, as `dexmill run --color MODE` draws them, its legend
 * included (display/view/colour_legend.h): slope bands of the surface's
 * angle; tool, the tool that last cut each column (needs dm_job.provenance;
 * named by dm_job.tools, else every T is dm_job.tool); material, the
 * material under the top with its texture (needs dm_job.material); thin,
 * floors thinner than thin_nm (the CLI's --thin); error, the distance to
 * the design (needs dm_job.design; its gouges are marked in red in every
 * mode, as the CLI marks them). Plain: the workpiece's one colour, as after dm_view_create. */
enum {
  DM_COLOUR_PLAIN = 0, DM_COLOUR_SLOPE = 1, DM_COLOUR_TOOL = 2, DM_COLOUR_MATERIAL = 3, DM_COLOUR_THIN = 4,
  DM_COLOUR_ERROR = 5
};
typedef struct dm_colour {
  int32_t mode;               /* DM_COLOUR_* */
  int32_t reserved;           /* 0 */
  int64_t thin_nm;            /* DM_COLOUR_THIN: 1 um .. 1 m (0: 1 mm, the CLI's default) */
} dm_colour;
/* Bytes of caller memory the mode needs for this view (its classes, a byte
 * a dexel, its ramps, its legend; material's texture, 4 or more bytes a
 * dexel more); 0 for plain. DM_E_ARGUMENT for an unknown mode or a thin_nm
 * out of range, DM_E_COLOUR for one the job cannot draw. */
DM_API dm_status dm_view_colour_bytes(const dm_view* view, const dm_colour* colour, size_t* bytes);
/* Draws the view in the mode from the next dm_render on, whole; mem
 * (8-byte aligned, at least dm_view_colour_bytes; NULL for plain) is the
 * mode's until the next dm_view_set_colour or dm_view_destroy. colour NULL:
 * plain. */
DM_API dm_status dm_view_set_colour(dm_view* view, const dm_colour* colour, void* mem, size_t bytes);
/* NULL is ignored. */
DM_API void dm_view_destroy(dm_view* view);

/* A decimal number of millimetres as text (the CLI's numbers: "-2.5",
 * "12", "0.000001"; spaces allowed) in nm, rounded to nearest. */
DM_API dm_status dm_mm_to_nm(const char* text, size_t n, int64_t* nm);

/* ---- the first pass: what `dexmill run FILE` chooses when not told ---- */
/* The program read once, nothing cut: the stock and grid `dexmill run`
 * takes with no --stock, --pitch or --grid (the program's (WORKPIECE,...)
 * or BLK FORM comments' box, else its motion's box widened by the largest
 * tool; the pitch from the smallest tool loaded: core/sim/stock_plan.h),
 * the units, the motion's box, the counts and the tools it loads. Fed and
 * stepped as a dm_sim is (the same lending of text); it stops at the
 * first input error or at an M6 of a T the job's tools lack, as the CLI's
 * pass does. A job's stock and grid are not read. */
typedef struct dm_scan dm_scan;
enum {  /* dm_scan_result.stock_from */
  DM_STOCK_FROM_PROGRAM = 0,       /* the motion's box */
  DM_STOCK_FROM_WORKPIECE = 1,     /* a (WORKPIECE,box,...) comment */
  DM_STOCK_FROM_WORKPIECE_BOX = 2, /* the box of a cylinder's or tube's (WORKPIECE,...) comment */
  DM_STOCK_FROM_BLK_FORM = 3       /* BLK FORM 0.1 / 0.2 comments */
};
enum { DM_UNITS_NONE = -1, DM_UNITS_MIXED = 2 };  /* dm_scan_result.units besides DM_UNITS_MM, DM_UNITS_INCH */
typedef struct dm_scan_result {
  dm_box stock;               /* the default stock, machine coordinates */
  int32_t stock_from;         /* DM_STOCK_FROM_* */
  int32_t units;              /* what its moves were written in: DM_UNITS_*, DM_UNITS_MIXED, DM_UNITS_NONE (no move) */
  int64_t pitch_nm;           /* the default pitch for that stock */
  int32_t grid_nx, grid_ny;   /* the grid it gives, dexels (dm_grid_info's, the ring of empty ones included) */
  int32_t has_extents;        /* non-zero: extents holds the motion's box */
  int32_t ntools;             /* tools loaded (dm_scan_tool_get), [0] the one before any M6 */
  dm_box extents;             /* every move's box (rapids included), machine coordinates */
  uint64_t rapids, feeds, arcs, dwells, tool_changes; /* records counted */
  uint32_t lines;             /* program lines read */
  uint32_t errors;            /* input errors: the pass stops at the first (0 or 1) */
  uint32_t error_line, error_col; /* the first one's, 1-based (0: none) */
  int32_t error_code;         /* its stable G-code error number */
  uint32_t bad_tool_line;     /* the M6 of a T the job's tools lack (0: none); the cut stops there too */
  int32_t bad_tool;           /* that T */
  uint32_t workpiece_bad_line; /* a (WORKPIECE,...) or BLK FORM comment not read (0: none): the CLI's warning */
  int64_t estimated_us;       /* the time model's estimate (no look-ahead) */
  int32_t table_units;        /* DM_UNITS_*: what a tool table for it is read in (core/sim/tool_units.h: the
                                 program's at its first T word when set by then, else dm_job.units) */
  int32_t reserved;
} dm_scan_result;
typedef struct dm_scan_tool {
  int32_t number;             /* the T number; -1 for the job's tool before any M6 */
  int32_t shape;              /* DM_TOOL_* */
  int64_t diameter_nm;
  uint32_t first_line;        /* the M6 that first loaded it ([0]: its first cutting move's line; 0: none) */
  uint32_t last_line;         /* its last feed or arc move's line (0: none) */
} dm_scan_tool;

/* Bytes a scan of the job needs (its tool, tools, units, max_blocks and
 * input_buffer_bytes are read; not its stock or grid). */
DM_API dm_status dm_scan_bytes(const dm_job* job, size_t* bytes);
/* Sets the scan up in mem (8-byte aligned, at least dm_scan_bytes). */
DM_API dm_status dm_scan_create(const dm_job* job, void* mem, size_t bytes, dm_scan** out);
/* As dm_feed, dm_input_taken and dm_end_input. */
DM_API dm_status dm_scan_feed(dm_scan* scan, const char* text, size_t n);
DM_API int32_t dm_scan_input_taken(const dm_scan* scan);
DM_API dm_status dm_scan_end_input(dm_scan* scan);
/* Reads until budget->lines lines (NULL or 0: no limit; the other counts
 * are not read) or input is needed: *state DM_READY, DM_NEED_INPUT, DM_DONE,
 * or DM_IO_ERROR (the input could not be read again for an o-word jump). */
DM_API dm_status dm_scan_step(dm_scan* scan, const dm_budget* budget, int32_t* state);
/* What it found, once DM_DONE (else DM_E_STATE). DM_E_GRID (the rest
 * filled, grid_nx and grid_ny 0) when the default stock makes no grid
 * (over 65535 dexels a side), as `dexmill run` then refuses. */
DM_API dm_status dm_scan_get_result(const dm_scan* scan, dm_scan_result* out);
/* Tool k (0 .. ntools - 1) it loaded; DM_E_INDEX past them. */
DM_API dm_status dm_scan_tool_get(const dm_scan* scan, int32_t k, dm_scan_tool* out);
/* Fills in what the job leaves to `dexmill run`'s defaults: the stock when
 * its box is all 0 (no --stock), the pitch for that stock (the given one's
 * or the default) when pitch_nm, grid_nx and grid_ny are all 0 (no --pitch
 * or --grid). Then dm_create cuts what `dexmill run` cuts. */
DM_API dm_status dm_scan_apply(const dm_scan* scan, dm_job* job);
/* NULL is ignored. */
DM_API void dm_scan_destroy(dm_scan* scan);

/* ---- tool tables ---- */
/* A LinuxCNC tool table's text (`dexmill run --tools FILE`; the format is
 * platform/format/tool_table.h's: T, D, Z for G43, the shape in the
 * comment) into job->tools[0, ntools) (their spec NULL, the fields set),
 * lengths in inch when `inch` is non-zero (dm_scan_result.table_units, the
 * rule `dexmill run` reads a table by). A row of D0 (no cutter) is left
 * out: a T the job lacks, as `dexmill run` cannot cut with it either; a
 * flat end mill guessed from a comment is not said here, and a comment
 * spec's holder and flutes are not kept (dm_tool has no fields for them:
 * the safety checks and chip loads differ from the CLI's for such a row). DM_E_TOOL_TABLE:
 * a line that does not read, *line and *col (1-based) where, message
 * (NUL terminated, at most message_bytes - 1 bytes; may be NULL) why, as
 * the CLI says it; DM_E_TOOL_NUMBER: more than DM_TOOLS_MAX tools (*line
 * the first one over). job->ntools is 0 after an error. */
DM_API dm_status dm_tool_table_parse(const char* text, size_t n, int32_t inch, dm_job* job, uint32_t* line, uint32_t* col,
                                     char* message, size_t message_bytes);

/* ---- the built-in demo ---- */
/* The program `dexmill run --demo pocket` (and `make run`) cuts, into
 * buf[0, n), NUL terminated (at most n - 1 bytes): its whole length (buf
 * NULL and n 0 to size it; about 108 KB). */
DM_API size_t dm_demo_program(char* buf, size_t n);
enum { DM_DEMO_STOCK = 0, DM_DEMO_TOOL_TABLE = 1, DM_DEMO_MATERIAL = 2 };
/* The demo's job as the CLI's texts: DM_DEMO_STOCK "X0,Y0,Z0,X1,Y1,Z1" (mm,
 * dm_mm_to_nm each), DM_DEMO_TOOL_TABLE its LinuxCNC table
 * (dm_tool_table_parse, mm), DM_DEMO_MATERIAL its material preset; NULL for
 * another number. */
DM_API const char* dm_demo_text(int32_t which);

/* ---- for bindings: the size of each struct as this library has it ---- */
enum {
  DM_STRUCT_JOB = 1, DM_STRUCT_TOOL, DM_STRUCT_BOX, DM_STRUCT_TRIANGLE, DM_STRUCT_BUDGET, DM_STRUCT_PROGRESS,
  DM_STRUCT_GRID_INFO, DM_STRUCT_COLUMN, DM_STRUCT_FINDING, DM_STRUCT_INPUT_ERROR, DM_STRUCT_FRAME,
  DM_STRUCT_CAMERA, DM_STRUCT_RECT, DM_STRUCT_SCAN_RESULT = 14, DM_STRUCT_SCAN_TOOL = 15,
  DM_STRUCT_COLOUR = 16
};
/* 0 for an unknown one. */
DM_API size_t dm_struct_bytes(int32_t which);

#ifdef __cplusplus
}
#endif

#endif
