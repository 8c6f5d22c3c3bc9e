/* embed.c - dexmill in a C program, through its C API (dexmill.h) and its
 * image files (dexmill_io.h): reads a G-code file in 4 KB pieces, cuts it
 * a few moves per step, redraws the picture as it goes (only what changed)
 * and writes the last frame as a PPM, the bytes `dexmill run FILE --stock
 * BOX --tool SPEC --grid NXxNY --size WxH --image OUT.ppm` writes.
 *
 *   embed FILE OUT.ppm X0,Y0,Z0,X1,Y1,Z1 TOOL NXxNY WxH
 *
 * Build: cc -std=c99 embed.c $(pkg-config --cflags --libs dexmill)
 * Exit: 0 the program ran, 1 it has input errors, 2 usage, 3 I/O.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dexmill.h"
#include "dexmill_io.h"

#define PIECE 4096

static int fail(int code, const char* what, dm_status s) {
  fprintf(stderr, "embed: %s: %s\n", what, dm_status_message(s));
  return code;
}

/* Six comma-separated mm values of the stock box. */
static int parse_box(const char* s, dm_box* box) {
  int64_t v[6];
  int k;
  for (k = 0; k < 6; ++k) {
    const char* end = strchr(s, ',');
    size_t n = end ? (size_t)(end - s) : strlen(s);
    if ((k < 5) != (end != NULL) || dm_mm_to_nm(s, n, &v[k]) != DM_OK) return 0;
    s = end ? end + 1 : s + n;
  }
  for (k = 0; k < 3; ++k) {
    box->lo_nm[k] = v[k];
    box->hi_nm[k] = v[k + 3];
  }
  return 1;
}

/* "AxB" as two positive numbers. */
static int parse_pair(const char* s, int32_t* a, int32_t* b) {
  char* end;
  long x = strtol(s, &end, 10), y;
  if (*end != 'x') return 0;
  y = strtol(end + 1, &end, 10);
  if (*end || x < 1 || y < 1 || x > 65535 || y > 65535) return 0;
  *a = (int32_t)x;
  *b = (int32_t)y;
  return 1;
}

/* 8-byte aligned memory for a handle. */
static void* block(size_t n) { return calloc(n / 8 + 1, 8); }

int main(int argc, char** argv) {
  dm_job job;
  dm_sim* sim = NULL;
  dm_view* view = NULL;
  dm_frame frame;
  dm_budget budget;
  dm_progress p;
  size_t bytes;
  dm_status s;
  void *sim_mem, *view_mem;
  char piece[PIECE];
  int32_t state = DM_READY, w, h;
  uint32_t k;
  long renders = 0;
  int at_end = 0;
  FILE* in;

  if (argc != 7) {
    fprintf(stderr, "usage: embed FILE OUT.ppm X0,Y0,Z0,X1,Y1,Z1 TOOL NXxNY WxH\n");
    return 2;
  }
  if ((s = dm_job_init(&job, DEXMILL_API_VERSION)) != DM_OK) return fail(2, "dm_job_init", s);
  job.tool.spec = argv[4];
  if (!parse_box(argv[3], &job.stock) || !parse_pair(argv[5], &job.grid_nx, &job.grid_ny) ||
      !parse_pair(argv[6], &w, &h)) {
    fprintf(stderr, "embed: bad stock box, grid or size\n");
    return 2;
  }
  if ((s = dm_required_bytes(&job, &bytes)) != DM_OK) return fail(2, "the job", s);
  sim_mem = block(bytes);
  if ((s = dm_create(&job, sim_mem, bytes, &sim)) != DM_OK) return fail(2, "dm_create", s);

  /* The picture: XRGB8888 at the size asked for, drawn as the run goes. */
  frame.width = w;
  frame.height = h;
  frame.stride_bytes = w * 4;
  frame.format = DM_XRGB8888;
  frame.pixels = block((size_t)frame.stride_bytes * (size_t)h);
  if ((s = dm_view_bytes(sim, w, h, &bytes)) != DM_OK) return fail(2, "dm_view_bytes", s);
  view_mem = block(bytes);
  if ((s = dm_view_create(sim, &frame, NULL, view_mem, bytes, &view)) != DM_OK) return fail(2, "dm_view_create", s);

  in = fopen(argv[1], "rb");
  if (!in) {
    perror(argv[1]);
    return 3;
  }
  memset(&budget, 0, sizeof budget);
  budget.moves = 4; /* a small slice: a controller's idle loop draws or polls between */
  while (state == DM_READY || state == DM_NEED_INPUT) {
    if ((s = dm_step(sim, &budget, &state)) != DM_OK) return fail(3, "dm_step", s);
    if (state == DM_NEED_INPUT) {
      /* The piece fed before is taken: the buffer may be refilled. */
      size_t got = at_end ? 0 : fread(piece, 1, sizeof piece, in);
      if (got > 0) s = dm_feed(sim, piece, got);
      else {
        at_end = 1;
        s = dm_end_input(sim);
      }
      if (s != DM_OK) return fail(3, "feeding", s);
    } else {
      /* Redraws what the slice changed; rects say where (to present). */
      int32_t n;
      dm_rect rects[DM_RECTS_MAX];
      if ((s = dm_render(view, rects, DM_RECTS_MAX, &n)) != DM_OK) return fail(3, "dm_render", s);
      ++renders;
    }
  }
  if (ferror(in)) {
    perror(argv[1]);
    return 3;
  }
  fclose(in);
  {
    int32_t n;
    char err[512];
    if ((s = dm_render(view, NULL, 0, &n)) != DM_OK) return fail(3, "dm_render", s);
    if ((s = dm_io_write_image(argv[2], &frame, err, sizeof err)) != DM_OK) {
      fprintf(stderr, "embed: %s\n", err[0] ? err : dm_status_message(s));
      return 3;
    }
  }

  dm_get_progress(sim, &p);
  printf("moves=%llu lines=%u renders=%ld removed_mm3=%llu.%03llu findings=%u errors=%u\n", (unsigned long long)p.moves,
         p.lines_read, renders, (unsigned long long)(p.removed_um3 / 1000000000u),
         (unsigned long long)(p.removed_um3 % 1000000000u / 1000000u), dm_finding_count(sim), p.errors);
  for (k = 0; k < p.errors && k < 16; ++k) {
    dm_input_error e;
    char msg[256];
    dm_error_get(sim, k, &e);
    dm_error_message(sim, k, msg, sizeof msg);
    fprintf(stderr, "%s:%u:%u: error: %s\n", argv[1], e.line, e.col, msg);
  }
  dm_view_destroy(view);
  dm_destroy(sim);
  free(view_mem);
  free(frame.pixels);
  free(sim_mem);
  return p.errors ? 1 : 0;
}
