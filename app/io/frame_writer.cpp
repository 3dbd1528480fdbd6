#include "io/frame_writer.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "springlab/error.hpp"
#include "util/atomic_file.hpp"

extern char** environ;

namespace springlab::app {

FrameWriter::~FrameWriter() { stop(); }

void FrameWriter::start() { thread_ = std::thread([this] { run(); }); }

void FrameWriter::stop() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void FrameWriter::push(Image frame, int index) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return queue_.size() < kQueue || error_; });
  if (error_) std::rethrow_exception(error_);
  queue_.emplace_back(std::move(frame), index);
  changed_.notify_all();
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
      throw std::runtime_error("--video needs ffmpeg, which is not installed: apt-get install ffmpeg "
                               "(scripts/setup.sh installs it), or write PNG frames with --out DIR");
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    std::ostringstream size, rate;
    size << width << "x" << height;
    rate.precision(17);
    rate << fps;
    const std::string sz = size.str(), fr = rate.str(), out = temp_.path().string();
    const char* argv[] = {ffmpeg.c_str(), "-nostdin", "-loglevel", "error", "-y", "-f", "rawvideo",
                          "-pix_fmt", "rgba", "-s", sz.c_str(), "-r", fr.c_str(), "-i", "-",
                          "-c:v", "libx264", "-preset", "veryfast", "-pix_fmt", "yuv420p",
                          "-movflags", "+faststart", "-f", "mp4", out.c_str(), nullptr};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
    posix_spawn_file_actions_addclose(&actions, fds[1]);
    const int rc = posix_spawn(&pid_, ffmpeg.c_str(), &actions, nullptr, const_cast<char**>(argv), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[0]);
    if (rc != 0) {
      ::close(fds[1]);
      throw std::runtime_error(std::string("ffmpeg could not be started: ") + std::strerror(rc));
    }
    pipe_ = fds[1];
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
  void write(const Image& frame, int) override {
    const std::uint8_t* p = frame.rgba.data();
    std::size_t left = frame.rgba.size();
    while (left > 0) {
      const ssize_t n = ::write(pipe_, p, left);
      if (n < 0) {
        if (errno == EINTR) continue;
        throw std::runtime_error("ffmpeg stopped taking frames (" + std::string(std::strerror(errno)) +
                                 "): is the disk full?");
      }
      p += n;
      left -= static_cast<std::size_t>(n);
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

std::unique_ptr<FrameWriter> mp4_video(const std::filesystem::path& file, int width, int height, double fps) {
  return std::make_unique<Mp4Video>(file, width, height, fps);
}

std::string find_executable(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

}  // namespace springlab::app
