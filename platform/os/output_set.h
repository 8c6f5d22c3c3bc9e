// The outputs of one run, published together. While an OutputSet is open
// (one at a time), OutputFile::commit() of a file that is replaced writes,
// flushes and closes its temporary (still locked: platform/os/temp_file.h)
// and leaves the rename to publish(), which renames every temporary, in
// the order committed, in one pass at the end, with SIGINT, SIGTERM and
// SIGHUP held off until it is done. What a reader of the folder may find:
// - before the pass, every output as it was; after it, every one new;
// - a rename that fails stops the pass: the outputs committed before it
//   are new, it and those after it as they were, and the run fails (exit 3);
// - SIGKILL or a power cut during the pass (a rename each, microseconds)
//   leaves those renamed so far new: commit the report last, and a new
//   report means every output it lists is new (`dexmill run` does);
// - an output that is written in place (standard output, a device, a
//   FIFO) is written at its commit, before the pass.
// Until the pass the new files and the old ones are on disk together.
#ifndef DEXMILL_PLATFORM_OS_OUTPUT_SET_H
#define DEXMILL_PLATFORM_OS_OUTPUT_SET_H

#include <cstdint>
#include <string>
#include <vector>

#include "platform/os/temp_file.h"

namespace dexmill {

class OutputSet {
 public:
  OutputSet();   // opens the set: commits join it
  ~OutputSet();  // closes it; temporaries not published are removed
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // An output committed to the set: its name as given, and its bytes.
  struct Output {
    std::string path;
    uint64_t bytes = 0;
  };
  const std::vector<Output>& outputs() const { return outputs_; }
  // Bytes committed under `path` (as given); -1 when none was.
  int64_t bytes_of(const std::string& path) const;

  // The renames. False with the first failure's message ("cannot write
  // 'x': ...") in *err.
  bool publish(std::string* err);

  // For OutputFile: the open set (null: none), an output written in place,
  // and a temporary handed over with its rename (the set owns it, its lock
  // and its cleanup slot from then on).
  static OutputSet* current();
  void written(const std::string& path, uint64_t bytes);
  void adopt(const std::string& path, uint64_t bytes, const std::string& target, LockedTemp* tmp, int cleanup_slot);

 private:
  struct Rename {
    std::string path, target;
    LockedTemp tmp;
    int cleanup_slot;
  };
  void drop(Rename* r, bool remove);
  std::vector<Output> outputs_;
  std::vector<Rename> renames_;
  OutputSet* outer_ = nullptr;
};

}  // namespace dexmill

#endif
