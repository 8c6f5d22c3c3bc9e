// The input guard; see file_guard.h.
#include "platform/input/file_guard.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "platform/live/frame_files.h"
#include "platform/os/output_file.h"
#include "platform/os/path_name.h"

namespace dexmill {

bool FileGuard::add_place(Entry* e, const std::string& path) {
  struct stat st;
  if (stat(folder_of(path).c_str(), &st) != 0) return false;
  e->places.push_back(Place{st.st_dev, st.st_ino, name_of(path)});
  return true;
}

bool FileGuard::same_file(const Entry& a, const Entry& b) {
  if (a.has_file && b.has_file && a.dev == b.dev && a.ino == b.ino) return true;
  for (const Place& p : a.places)
    for (const Place& q : b.places)
      if (!p.name.empty() && p.dev == q.dev && p.ino == q.ino && p.name == q.name) return true;
  return false;
}

std::string FileGuard::describe(const Entry& e) {
  switch (e.kind) {
    case Kind::kInput: return "the input " + e.label + " '" + e.path + "'";
    case Kind::kOutput:
      if (e.standard_output) return e.label.empty() ? "standard output" : "standard output (" + e.label + ")";
      return e.label + " '" + e.path + "'";
    default: return e.label + " '" + e.owner + "'";
  }
}

bool FileGuard::clash(const Entry& n, const Entry& x) {
  if (n.standard_output && x.standard_output) {
    message_ = x.label + " and " + n.label + " both write to standard output ('-'); only one can";
    return true;
  }
  // The frames take every frame name in their folder, whether it is there
  // yet or not.
  if (n.kind == Kind::kFrames || x.kind == Kind::kFrames) {
    const Entry& f = n.kind == Kind::kFrames ? n : x;
    const Entry& o = n.kind == Kind::kFrames ? x : n;
    if (o.kind != Kind::kInput && o.kind != Kind::kOutput) return false;
    for (const Place& p : o.places)
      if (p.dev == f.places[0].dev && p.ino == f.places[0].ino && is_frame_name(p.name.c_str())) {
        message_ = describe(f) + " would write '" + f.owner + "/" + p.name + "', which is " + describe(o);
        return true;
      }
    return false;
  }
  if (n.kind == Kind::kRemoval || x.kind == Kind::kRemoval) {
    const Entry& r = n.kind == Kind::kRemoval ? n : x;
    const Entry& o = n.kind == Kind::kRemoval ? x : n;
    // An input registered after the removal is not what it removed: that
    // one is gone (and its inode may be a new file's).
    if (o.kind == Kind::kRemoval || (o.kind == Kind::kInput && &o == &n) || !same_file(r, o)) return false;
    message_ = describe(r) + " would remove '" + r.path + "', which is " + describe(o);
    return true;
  }
  if (n.kind == Kind::kInput && x.kind == Kind::kInput) return false;
  if (!same_file(n, x)) return false;
  if (n.kind == Kind::kOutput && x.kind == Kind::kOutput) {
    message_ = describe(x) + " and " + describe(n) + " are the same file";
    return true;
  }
  const Entry& in = n.kind == Kind::kInput ? n : x;
  const Entry& out = n.kind == Kind::kInput ? x : n;
  if (!out.standard_output && !out.may_be.empty() && out.may_be == in.label) return false;
  message_ = describe(out) + " is " + describe(in) +
             (!out.standard_output ? "; refusing to overwrite it"
              : out.appends        ? "; refusing to append to it"
                                   : ", which the shell has emptied already");
  return true;
}

FileGuard::Verdict FileGuard::add(const Entry& n) {
  for (const Entry& x : entries_)
    if (clash(n, x)) return Verdict::kClash;
  entries_.push_back(n);
  return Verdict::kOk;
}

FileGuard::Verdict FileGuard::cannot_write(const std::string& why) {
  message_ = "cannot write " + why;
  return Verdict::kCannotWrite;
}

FileGuard::Verdict FileGuard::register_input(const std::string& path, const char* what) {
  struct stat st;
  if (path.empty() || is_stdout_path(path) || stat(path.c_str(), &st) != 0) return Verdict::kOk;
  Entry e(Kind::kInput, what, path);
  e.has_file = true;
  e.dev = st.st_dev;
  e.ino = st.st_ino;
  std::string target;
  if (output_target(path, &target)) add_place(&e, target);
  return add(e);
}

FileGuard::Verdict FileGuard::check_output(const std::string& option, const std::string& path, const char* may_be) {
  Entry e(Kind::kOutput, option, path);
  if (may_be) e.may_be = may_be;
  struct stat st;
  if (is_stdout_path(path)) {
    e.standard_output = true;
    if (fstat(STDOUT_FILENO, &st) == 0 && S_ISREG(st.st_mode)) {
      e.has_file = true;
      e.dev = st.st_dev;
      e.ino = st.st_ino;
      const int flags = fcntl(STDOUT_FILENO, F_GETFL);
      e.appends = flags >= 0 && (flags & O_APPEND);
    }
    return add(e);
  }
  const std::string named = option + " '" + path + "'";
  std::string target;
  if (!output_target(path, &target)) return cannot_write(named + ": " + std::strerror(errno));
  if (stat(target.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) return cannot_write(named + ": it is a directory");
    if (!S_ISREG(st.st_mode)) {  // written through, never replaced: no clash
      if (access(target.c_str(), W_OK) != 0) return cannot_write(named + ": " + std::strerror(errno));
      return Verdict::kOk;
    }
    e.has_file = true;
    e.dev = st.st_dev;
    e.ino = st.st_ino;
  }
  // A regular file is replaced by a rename in its folder
  // (platform/os/output_file.h): the folder must be there and writable.
  const std::string dir = folder_of(target);
  struct stat dst;
  const bool found = stat(dir.c_str(), &dst) == 0;
  if (!found || !S_ISDIR(dst.st_mode)) {
    const bool missing = found || errno == ENOENT || errno == ENOTDIR;
    return cannot_write(named + ": " +
                        (missing ? "no directory '" + dir + "'" : "directory '" + dir + "': " + std::strerror(errno)));
  }
  if (access(dir.c_str(), W_OK) != 0) return cannot_write(named + ": directory '" + dir + "' is not writable");
  add_place(&e, target);
  if (target != path) add_place(&e, path);  // a link a clean-up could remove first
  return add(e);
}

FileGuard::Verdict FileGuard::check_removal(const std::string& option, const std::string& owner, const std::string& path) {
  Entry e(Kind::kRemoval, option, path);
  e.owner = owner;
  struct stat st;
  if (stat(path.c_str(), &st) == 0) {
    e.has_file = true;
    e.dev = st.st_dev;
    e.ino = st.st_ino;
  }
  add_place(&e, path);
  return add(e);
}

FileGuard::Verdict FileGuard::check_frames(const std::string& option, const std::string& dir) {
  struct stat st;
  if (stat(dir.c_str(), &st) != 0) return Verdict::kOk;  // nothing is in a folder that is not there
  Entry e(Kind::kFrames, option, dir);
  e.owner = dir;
  e.places.push_back(Place{st.st_dev, st.st_ino, std::string()});
  return add(e);
}

}  // namespace dexmill
