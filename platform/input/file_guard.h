// The input guard: a command never writes or removes a file it
// reads, nor writes one file as two outputs. A command makes one FileGuard
// and, before it writes or removes anything, registers every file it reads
// and checks every file it will write or remove; each call compares the
// file with all those before it. A file opened later (a subroutine file, at
// the call that needs it: platform/input/gcode_file.h) is registered then, and
// compared with the outputs checked before the run.
//
// When two names are one file:
// - an existing file is its device and inode after symbolic links, so
//   another name for it, a link to it and a hard link of it are it;
// - a name is also a place: its folder's device and inode and its last
//   component, after the links (and for an output or a removal, as given
//   too), so that a new "a.png" and "out/../a.png" meet, and a frame's name
//   in the frames folder is known before the frame exists.
// A device, FIFO or socket an output names is written to, never replaced
// (platform/os/output_file.h): it is no clash (/dev/null may be two outputs).
// Standard output ("-") is what the shell opened: a regular file there is
// that file, and a second output on "-" is refused.
#ifndef DEXMILL_PLATFORM_INPUT_FILE_GUARD_H
#define DEXMILL_PLATFORM_INPUT_FILE_GUARD_H

#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace dexmill {

class FileGuard {
 public:
  enum class Verdict : uint8_t {
    kOk,
    kClash,        // two of the files are one (a usage error); message() names both
    kCannotWrite,  // an output that cannot be written: a directory, its folder missing or not writable
  };
  // The `what` of the program; an output may be allowed to replace it
  // (check_output's may_be).
  static constexpr const char* kProgram = "program";

  // A file the command reads; `what` names it in messages ("program",
  // "--tools", "subroutine"). An empty name, "-" and a name that is not
  // there are skipped (their reading fails on its own terms). kClash when
  // it is an output checked before.
  Verdict register_input(const std::string& path, const char* what);

  // A file the command writes, `option` naming it in messages ("--report",
  // "-o"; for "-", what writes to standard output, or empty). kClash when it
  // is an input, another output, or a name the frames or a clean-up take;
  // kCannotWrite as above. `may_be` names an input it may replace: one the
  // command reads whole before it writes (optimize -o FILE and its program).
  Verdict check_output(const std::string& option, const std::string& path, const char* may_be = nullptr);

  // A file the command removes: `option` 'owner' is the clean-up (--frames
  // 'DIR' removing an earlier run's frame). kClash when it is an input or
  // an output. Call it once the command's inputs are known, just before the
  // removal: inputs registered later are not compared with it (it is gone).
  Verdict check_removal(const std::string& option, const std::string& owner, const std::string& path);

  // The frames a run writes into the folder `dir` (which must exist), and
  // that the next run's clean-up removes: every frame-NNNNNN.png and .ppm
  // there (platform/live/frame_files.h). kClash when an input or output is one.
  Verdict check_frames(const std::string& option, const std::string& dir);

  // Why the last call that did not return kOk did not.
  const std::string& message() const { return message_; }

 private:
  struct Place {
    dev_t dev;
    ino_t ino;
    std::string name;  // empty: the folder itself (the frames')
  };
  enum class Kind : uint8_t { kInput, kOutput, kRemoval, kFrames };
  struct Entry {
    Entry(Kind k, const std::string& l, const std::string& p) : kind(k), label(l), path(p) {}
    Kind kind;
    std::string label;      // what or option
    std::string path;       // as given
    std::string owner;      // a removal's or the frames' folder as given
    std::string may_be;     // an output: the input it may replace
    bool has_file = false;  // dev and ino of an existing file
    dev_t dev = 0;
    ino_t ino = 0;
    std::vector<Place> places;
    bool standard_output = false;
    bool appends = false;   // standard output opened for appending (>>)
  };

  // Where the name `path` is (its folder, after no link), added to e's
  // places; false when its folder is not there.
  static bool add_place(Entry* e, const std::string& path);
  static bool same_file(const Entry& a, const Entry& b);
  static std::string describe(const Entry& e);
  // Compares n with every entry so far, then keeps it.
  Verdict add(const Entry& n);
  // True, with the message, when the new entry n and the earlier x clash.
  bool clash(const Entry& n, const Entry& x);
  Verdict cannot_write(const std::string& why);

  std::vector<Entry> entries_;
  std::string message_;
};

}  // namespace dexmill

#endif
