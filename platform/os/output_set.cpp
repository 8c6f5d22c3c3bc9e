// Outputs published together; see output_set.h.
#include "platform/os/output_set.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "platform/os/process.h"

namespace dexmill {

namespace {
OutputSet* g_current = nullptr;
}  // namespace

OutputSet::OutputSet() : outer_(g_current) { g_current = this; }

OutputSet::~OutputSet() {
  for (Rename& r : renames_) drop(&r, true);
  g_current = outer_;
}

OutputSet* OutputSet::current() { return g_current; }

int64_t OutputSet::bytes_of(const std::string& path) const {
  for (const Output& o : outputs_)
    if (o.path == path) return static_cast<int64_t>(o.bytes);
  return -1;
}

void OutputSet::written(const std::string& path, uint64_t bytes) { outputs_.push_back(Output{path, bytes}); }

void OutputSet::adopt(const std::string& path, uint64_t bytes, const std::string& target, LockedTemp* tmp, int cleanup_slot) {
  written(path, bytes);
  renames_.push_back(Rename{path, target, *tmp, cleanup_slot});
  *tmp = LockedTemp();
}

// Forgets a temporary: removed first when `remove` (the lock after: a
// clean-up never finds it unlocked under its temporary name).
void OutputSet::drop(Rename* r, bool remove) {
  if (r->tmp.path.empty()) return;
  if (remove) unlink(r->tmp.path.c_str());
  release_locked_temp(&r->tmp);
  r->tmp.path.clear();
  cleanup_unregister(r->cleanup_slot);
}

bool OutputSet::publish(std::string* err) {
  // A signal that comes during the renames is acted on when they are done:
  // nothing is then left to remove.
  const StopSignalsHeld held;
  bool ok = true;
  for (Rename& r : renames_) {
    if (ok && std::rename(r.tmp.path.c_str(), r.target.c_str()) != 0) {
      *err = "cannot write '" + r.path + "': " + std::strerror(errno);
      ok = false;
    }
    drop(&r, !ok);
  }
  renames_.clear();
  return ok;
}

}  // namespace dexmill
