#include "io/frame_writer.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/uio.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "springlab/error.hpp"
#include "util/atomic_file.hpp"

extern char** environ;

namespace springlab::app {

FrameWriter::~FrameWriter() {
  stop();
}

void FrameWriter::start() {
  thread_.start([this] { run(); });
}

void FrameWriter::stop() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void FrameWriter::push(Image frame, int index) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return queue_.size() < kQueue || error_; });
  if (error_) std::rethrow_exception(error_);
  queue_.emplace_back(std::move(frame), index);
  changed_.notify_all();
}

Image FrameWriter::spare() {
  std::lock_guard lock(mutex_);
  if (spares_.empty()) return {};
  Image image = std::move(spares_.back());
  spares_.pop_back();
  return image;
}

void FrameWriter::finish() {
  stop();
  if (error_) std::rethrow_exception(error_);
  complete();
}

void FrameWriter::run() {
  for (;;) {
    std::pair<Image, int> item;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return !queue_.empty() || closing_; });
      if (queue_.empty()) return;
      item = std::move(queue_.front());
      queue_.pop_front();
    }
    changed_.notify_all();
    try {
      write(item.first, item.second);
      std::lock_guard lock(mutex_);
      if (spares_.size() < kQueue) spares_.push_back(std::move(item.first));
    } catch (...) {
      std::lock_guard lock(mutex_);
      error_ = std::current_exception();
      queue_.clear();
      changed_.notify_all();
      return;
    }
  }
}

namespace {

class PngSequence final : public FrameWriter {
 public:
  explicit PngSequence(std::filesystem::path dir) : dir_(std::move(dir)) { start(); }
  ~PngSequence() override { stop(); }

 protected:
  void write(const Image& frame, int index) override {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", index);
    write_png(dir_ / name, frame, 1);
  }
  void complete() override {}

 private:
  std::filesystem::path dir_;
};

class Mp4Video final : public FrameWriter {
 public:
  Mp4Video(const std::filesystem::path& file, int width, int height, double fps)
      : temp_(file, "video"), width_(width), height_(height) {
    const std::string ffmpeg = find_executable("ffmpeg");
    if (ffmpeg.empty())
      throw std::runtime_error(
          "--video needs ffmpeg, which is not installed: apt-get install ffmpeg "
          "(scripts/setup.sh installs it), or write PNG frames with --out DIR");
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    std::ostringstream size, rate;
    size << width << "x" << height;
    rate.precision(17);
    rate << fps;
    const std::string sz = size.str(), fr = rate.str(), out = temp_.path().string();
    const char* argv[] = {ffmpeg.c_str(), "-nostdin",  "-loglevel",  "error",    "-y",
                          "-f",           "rawvideo",  "-pix_fmt",   "rgba",     "-s",
                          sz.c_str(),     "-r",        fr.c_str(),   "-i",       "-",
                          "-c:v",         "libx264",   "-preset",    "veryfast", "-pix_fmt",
                          "yuv420p",      "-movflags", "+faststart", "-f",       "mp4",
                          out.c_str(),    nullptr};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
    posix_spawn_file_actions_addclose(&actions, fds[1]);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    unblock_interrupts_in_child(attributes);
    const int rc = posix_spawn(&pid_, ffmpeg.c_str(), &actions, &attributes,
                               const_cast<char**>(argv), environ);
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[0]);
    if (rc != 0) {
      ::close(fds[1]);
      throw std::runtime_error(std::string("ffmpeg could not be started: ") + std::strerror(rc));
    }
    pipe_ = fds[1];
    // A frame is megabytes: a larger pipe (best effort: 1 MiB is Linux's default limit) wakes
    // ffmpeg a few times a frame instead of every 64 KiB.
    ::fcntl(pipe_, F_SETPIPE_SZ, 1 << 20);
    start();
  }

  ~Mp4Video() override {
    stop();
    if (pipe_ >= 0) ::close(pipe_);
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
    }
  }

 protected:
  // The rows from the top, as ffmpeg takes them: one writev of up to kRows rows at a time,
  // whichever way the image holds them.
  void write(const Image& frame, int) override {
    constexpr int kRows = 512;  // below IOV_MAX (1024)
    const std::size_t row = static_cast<std::size_t>(frame.width) * 4;
    iovec rows[kRows];
    for (int top = 0; top < frame.height; top += kRows) {
      const int count = std::min(kRows, frame.height - top);
      for (int y = 0; y < count; ++y)
        rows[y] = {const_cast<std::uint8_t*>(frame.row(top + y)), row};
      send(rows, count);
    }
  }

  void send(iovec* rows, int count) {
    while (count > 0) {
      ssize_t n = ::writev(pipe_, rows, count);
      if (n < 0) {
        if (errno == EINTR) continue;
        throw std::runtime_error("ffmpeg stopped taking frames (" +
                                 std::string(std::strerror(errno)) + "): is the disk full?");
      }
      // Past what was written: whole rows, then part of one.
      while (count > 0 && static_cast<std::size_t>(n) >= rows->iov_len) {
        n -= static_cast<ssize_t>(rows->iov_len);
        ++rows;
        --count;
      }
      if (count > 0) {
        rows->iov_base = static_cast<std::uint8_t*>(rows->iov_base) + n;
        rows->iov_len -= static_cast<std::size_t>(n);
      }
    }
  }

  void complete() override {
    ::close(pipe_);
    pipe_ = -1;
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
      throw std::runtime_error("ffmpeg failed to encode '" + temp_.final_path().string() +
                               "' (see its message above); nothing was left behind");
    temp_.commit();
  }

 private:
  TemporaryPath temp_;
  int width_, height_;
  pid_t pid_ = -1;
  int pipe_ = -1;
};

}  // namespace

std::unique_ptr<FrameWriter> png_sequence(const std::filesystem::path& dir) {
  return std::make_unique<PngSequence>(dir);
}

std::unique_ptr<FrameWriter> mp4_video(const std::filesystem::path& file, int width, int height,
                                       double fps) {
  return std::make_unique<Mp4Video>(file, width, height, fps);
}

std::string find_executable(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

}  // namespace springlab::app
