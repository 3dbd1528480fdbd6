// Where rendered frames go: numbered PNG files in a folder, or an mp4 through ffmpeg. Frames are
// handed to a writer thread (at most `kQueue` waiting), so that compressing or encoding one
// overlaps rendering the next.
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <memory>
#include <mutex>
#include <vector>

#include "io/png.hpp"
#include "util/worker.hpp"

namespace springlab::app {

class FrameWriter {
 public:
  virtual ~FrameWriter();
  // Queues a frame (waits while the queue is full). Rethrows a failure of the writer thread.
  void push(Image frame, int index);
  // An image written already, to read the next frame into (its buffer is reused: a 1280x720
  // frame is 3.7 MB the system would otherwise map and clear each time); empty at first.
  Image spare();
  // Waits for every frame, then completes the output (renames, closes ffmpeg). Throws on failure.
  void finish();

 protected:
  void start();
  void stop();
  virtual void write(const Image& frame, int index) = 0;
  virtual void complete() = 0;

 private:
  static constexpr std::size_t kQueue = 3;
  void run();
  Worker thread_;  // (native builds only: the browser writes no frames)
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::pair<Image, int>> queue_;
  std::vector<Image> spares_;
  bool closing_ = false;
  std::exception_ptr error_;
};

// DIR/frame_00000.png, ...; each file appears only when complete.
std::unique_ptr<FrameWriter> png_sequence(const std::filesystem::path& dir);

// An H.264 mp4 (libx264, yuv420p) through an ffmpeg process fed raw RGBA on a pipe; written under
// a temporary name and renamed when ffmpeg has finished. Throws std::runtime_error at once, saying
// how to install it, when ffmpeg is missing; width and height must be even.
std::unique_ptr<FrameWriter> mp4_video(const std::filesystem::path& file, int width, int height,
                                       double fps);

// The full path of an executable on PATH, or "" when none.
std::string find_executable(const std::string& name);

}  // namespace springlab::app
