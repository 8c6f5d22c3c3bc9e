// The output files of `dexmill run`, checked before anything runs: each
// one's format from its extension, at most one on standard output ("-"),
// none the same file as an input or as another output, each one's folder
// there and writable (a long simulation must not end in "cannot write");
// the last three are the input guard's (platform/input/file_guard.h).
#ifndef DEXMILL_TOOLS_RUN_RUN_OUTPUTS_H
#define DEXMILL_TOOLS_RUN_RUN_OUTPUTS_H

#include <string>

#include "platform/input/file_guard.h"
#include "platform/format/image_file.h"
#include "tools/run/run_options.h"

namespace dexmill {
namespace cli {

struct OutputFormats {
  ImageFormat image = ImageFormat::kPng;
  ImageFormat error_image = ImageFormat::kPng;
  ImageFormat heightmap = ImageFormat::kPgm;
};

// The format an image output's name asks for: ".ppm" or ".png" (".pgm" or
// ".png" when `heightmap`), any case. A name without an extension that is
// standard output or an existing device or FIFO gets `fallback`. Else false
// with the usage message in *err.
bool output_format(const char* option, const std::string& path, bool heightmap, ImageFormat fallback,
                   ImageFormat* format, std::string* err);

// Picks the formats of the outputs of `o` and checks each with the guard
// (platform/input/file_guard.h: against the inputs registered before and each
// other). Returns kExitOk, or prints the error and returns kExitUsage (a
// bad extension, two outputs on standard output, an output that is an
// input or another output) or kExitIo (no such folder, not writable, a
// directory).
int check_outputs(const OutputOptions& o, FileGuard* guard, OutputFormats* formats);

}  // namespace cli
}  // namespace dexmill

#endif
