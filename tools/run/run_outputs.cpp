// The outputs of `dexmill run`, checked before the run; see run_outputs.h.
#include "tools/run/run_outputs.h"

#include <sys/stat.h>

#include <string>
#include <utility>

#include "platform/os/output_file.h"
#include "platform/os/path_name.h"
#include "tools/cli/cli.h"
#include "tools/run/guard_inputs.h"
#include "tools/cli/option_values.h"

namespace dexmill {
namespace cli {

namespace {

// An existing device, FIFO or socket (after links): written through, so
// its name needs no extension.
bool is_special(const std::string& path) {
  std::string target;
  struct stat st;
  return output_target(path, &target) && stat(target.c_str(), &st) == 0 && !S_ISREG(st.st_mode) &&
         !S_ISDIR(st.st_mode);
}

}  // namespace

bool output_format(const char* option, const std::string& path, bool heightmap, ImageFormat fallback,
                   ImageFormat* format, std::string* err) {
  if (has_extension(path, ".png")) {
    *format = ImageFormat::kPng;
  } else if (!heightmap && has_extension(path, ".ppm")) {
    *format = ImageFormat::kPpm;
  } else if (heightmap && has_extension(path, ".pgm")) {
    *format = ImageFormat::kPgm;
  } else if (is_stdout_path(path) || (name_of(path).find('.') == std::string::npos && is_special(path))) {
    *format = fallback;
  } else {
    *err = std::string(option) + " '" + path + "': the name must end in " + (heightmap ? ".pgm" : ".ppm") +
           " or .png (the format follows the extension)";
    return false;
  }
  return true;
}

int check_outputs(const OutputOptions& o, FileGuard* guard, OutputFormats* formats) {
  std::string err;
  if (!o.image.empty() && !output_format("--image", o.image, false, ImageFormat::kPng, &formats->image, &err))
    return fail(kExitUsage, "%s", err.c_str());
  if (!o.error_image.empty() &&
      !output_format("--error-image", o.error_image, false, ImageFormat::kPng, &formats->error_image, &err))
    return fail(kExitUsage, "%s", err.c_str());
  if (!o.heightmap.empty() &&
      !output_format("--heightmap", o.heightmap, true, ImageFormat::kPgm, &formats->heightmap, &err))
    return fail(kExitUsage, "%s", err.c_str());
  const std::pair<const char*, const std::string*> all[] = {
      {"--image", &o.image}, {"--error-image", &o.error_image}, {"--heightmap", &o.heightmap},
      {"--stl", &o.stl},     {"--save-stock", &o.save_stock}, {"--engagement-csv", &o.engagement_csv},
      {"--load-plot", &o.load_plot}, {"--sheet", &o.sheet}, {"--report", &o.report}};
  for (const auto& out : all)
    if (!out.second->empty())
      if (const int code = guard_status(*guard, guard->check_output(out.first, *out.second))) return code;
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
