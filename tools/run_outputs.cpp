// The outputs of `dexmill run`, checked before the run; see run_outputs.h.
#include "tools/run_outputs.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "platform/output_file.h"
#include "tools/cli.h"
#include "tools/option_values.h"

namespace dexmill {
namespace cli {

namespace {

std::string dir_of(const std::string& path) {
  const size_t slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

std::string base_of(const std::string& path) {
  const size_t slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// What a name stands for on disk: an existing file's device and inode, or
// a new file's folder and name, so that "a.png" and "./out/../a.png" meet.
struct FileId {
  dev_t dev = 0;
  ino_t ino = 0;
  std::string name;  // empty for an existing file
  bool operator==(const FileId& o) const { return dev == o.dev && ino == o.ino && name == o.name; }
};

struct Output {
  const char* option;
  const std::string* path;
  std::string target;  // after symbolic links
  bool regular = true; // a regular file or a new name (a device or FIFO is written through)
  FileId id;
};

// Resolves an output and checks that it can be written. kExitOk, or the
// exit status with the message in *err.
int inspect(Output* out, std::string* err) {
  const std::string& path = *out->path;
  if (!output_target(path, &out->target)) {
    *err = "cannot write the " + std::string(out->option + 2) + " '" + path + "': " + std::strerror(errno);
    return kExitIo;
  }
  struct stat st;
  if (stat(out->target.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) {
      *err = std::string(out->option) + " '" + path + "' is a directory";
      return kExitIo;
    }
    out->regular = S_ISREG(st.st_mode);
    out->id.dev = st.st_dev;
    out->id.ino = st.st_ino;
    if (!out->regular) {
      if (access(out->target.c_str(), W_OK) != 0) {
        *err = std::string(out->option) + " '" + path + "': " + std::strerror(errno);
        return kExitIo;
      }
      return kExitOk;
    }
  }
  // A regular file is replaced by a rename in its folder: the folder must
  // exist and be writable.
  const std::string dir = dir_of(out->target);
  struct stat dst;
  const bool found = stat(dir.c_str(), &dst) == 0;
  if (!found || !S_ISDIR(dst.st_mode)) {
    const bool missing = found || errno == ENOENT || errno == ENOTDIR;
    *err = std::string(out->option) + " '" + path + "': " +
           (missing ? "no directory '" + dir + "'" : "directory '" + dir + "': " + std::strerror(errno));
    return kExitIo;
  }
  if (access(dir.c_str(), W_OK) != 0) {
    *err = std::string(out->option) + " '" + path + "': directory '" + dir + "' is not writable";
    return kExitIo;
  }
  if (out->id.ino == 0) {
    out->id.dev = dst.st_dev;
    out->id.ino = dst.st_ino;
    out->id.name = base_of(out->target);
  }
  return kExitOk;
}

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
  } else if (is_stdout_path(path) || (base_of(path).find('.') == std::string::npos && is_special(path))) {
    *format = fallback;
  } else {
    *err = std::string(option) + " '" + path + "': the name must end in " + (heightmap ? ".pgm" : ".ppm") +
           " or .png (the format follows the extension)";
    return false;
  }
  return true;
}

int check_outputs(const OutputOptions& o, const std::vector<std::string>& inputs, OutputFormats* formats) {
  std::string err;
  if (!o.image.empty() && !output_format("--image", o.image, false, ImageFormat::kPng, &formats->image, &err))
    return fail(kExitUsage, "%s", err.c_str());
  if (!o.error_image.empty() &&
      !output_format("--error-image", o.error_image, false, ImageFormat::kPng, &formats->error_image, &err))
    return fail(kExitUsage, "%s", err.c_str());
  if (!o.heightmap.empty() &&
      !output_format("--heightmap", o.heightmap, true, ImageFormat::kPgm, &formats->heightmap, &err))
    return fail(kExitUsage, "%s", err.c_str());

  Output all[] = {{"--image", &o.image, {}, true, {}},
                  {"--error-image", &o.error_image, {}, true, {}},
                  {"--heightmap", &o.heightmap, {}, true, {}},
                  {"--stl", &o.stl, {}, true, {}},
                  {"--report", &o.report, {}, true, {}}};
  std::vector<Output*> files;
  const char* on_stdout = nullptr;
  for (Output& out : all) {
    if (out.path->empty()) continue;
    if (is_stdout_path(*out.path)) {
      if (on_stdout) return fail(kExitUsage, "%s and %s both write to standard output ('-'); only one can", on_stdout, out.option);
      on_stdout = out.option;
      continue;
    }
    const int code = inspect(&out, &err);
    if (code != kExitOk) return fail(code, "cannot write %s", err.c_str());
    if (out.regular) files.push_back(&out);
  }
  for (size_t a = 0; a < files.size(); ++a)
    for (size_t b = a + 1; b < files.size(); ++b)
      if (files[a]->id == files[b]->id)
        return fail(kExitUsage, "%s '%s' and %s '%s' are the same file", files[a]->option, files[a]->path->c_str(),
                    files[b]->option, files[b]->path->c_str());
  for (const std::string& in : inputs) {
    struct stat st;
    if (in.empty() || is_stdout_path(in) || stat(in.c_str(), &st) != 0) continue;
    for (const Output* out : files)
      if (out->id == FileId{st.st_dev, st.st_ino, {}})
        return fail(kExitUsage, "%s '%s' is the input '%s'; refusing to overwrite it", out->option, out->path->c_str(),
                    in.c_str());
  }
  return kExitOk;
}

}  // namespace cli
}  // namespace dexmill
