// A Screen whose every present() writes the whole frame as the next file of
// a numbered sequence: DIR/frame-000001.png, DIR/frame-000002.png, ... (or
// .ppm). The frame is XRGB8888 in memory this object owns.
#ifndef DEXMILL_PLATFORM_LIVE_FRAME_FILES_H
#define DEXMILL_PLATFORM_LIVE_FRAME_FILES_H

#include <cstdint>
#include <string>
#include <vector>

#include "platform/format/image_file.h"
#include "platform/live/screen.h"

namespace dexmill {

class FrameFiles final : public Screen {
 public:
  // Frames of width x height into `dir` (which must exist), as PNG or PPM.
  FrameFiles(const std::string& dir, ImageFormat format, int32_t width, int32_t height);

  FrameView frame() override { return view_; }
  bool present(const ScreenRect* rects, int count) override;
  const char* error() const override { return error_; }
  // Files written so far.
  uint32_t written() const { return written_; }

 private:
  std::string dir_;
  ImageFormat format_;
  std::vector<uint32_t> pixels_;
  FrameView view_;
  uint32_t written_ = 0;
  char error_[1300] = {0};
};

// Creates `dir` and its missing parents (mode 0777 before the umask). False
// with a message ("cannot create directory 'x': ...") on failure, including
// when a component exists and is not a directory.
bool make_dirs(const std::string& dir, std::string* err);

// frame-NNNNNN.png or frame-NNNNNN.ppm: the names FrameFiles writes.
bool is_frame_name(const char* name);

// The files of an earlier sequence in `dir` (frame-NNNNNN.png and .ppm,
// nothing else) as DIR/NAME: what a run removes before its first frame, so
// that a shorter run's frames are not mixed with a longer run's (each one
// checked first: platform/input/file_guard.h). False with a message when the
// folder cannot be read.
bool find_old_frames(const std::string& dir, std::vector<std::string>* paths, std::string* err);

// Removes the files find_old_frames found. False with a message when one
// cannot be removed.
bool remove_old_frames(const std::vector<std::string>& paths, std::string* err);

}  // namespace dexmill

#endif
