/* dexmill_io.h - image files of dexmill frames for embedders: the
 * platform's own encoders (platform/format/ppm.h, png.h, deflate.h: no library),
 * in libdexmill_io.a beside libdexmill. Hosted code (files, the C++
 * standard library: link with -lstdc++; pkg-config dexmill says so).
 *
 * C99, usable from C++; the frames and statuses are dexmill.h's.
 */
#ifndef DEXMILL_IO_H
#define DEXMILL_IO_H

#include <stddef.h>
#include <stdint.h>

#include "dexmill.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Writes the frame as `path`: a binary PPM (P6) for a name ending in .ppm,
 * a PNG for .png (the bytes `dexmill run --image` writes), complete or not
 * at all. DM_E_ARGUMENT for another name, DM_E_FRAME for a frame that
 * cannot be read, DM_E_IO when the file cannot be written (err, when not
 * NULL, gets why: errn bytes at most, NUL terminated). */
DM_API dm_status dm_io_write_image(const char* path, const dm_frame* frame, char* err, size_t errn);

/* The frame as a PNG file in memory: *bytes is its size; written to
 * out[0, *bytes) when cap is enough, else nothing (DM_E_MEMORY: ask again
 * with *bytes). */
DM_API dm_status dm_io_png(const dm_frame* frame, uint8_t* out, size_t cap, size_t* bytes);

#ifdef __cplusplus
}
#endif

#endif
