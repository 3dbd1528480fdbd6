// springlab render, as a user (or a course's CI) runs it: PNG frames and mp4 video headlessly,
// exact frame times, and every way it can fail: no ffmpeg, no EGL, an unwritable folder, bad
// options, an interruption; each with one message, its exit status and nothing half-written.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>

#include <chrono>
#include <thread>

#include "cli/cli_support.hpp"
#include "io/png.hpp"

namespace springlab::test {
namespace {

namespace fs = std::filesystem;

int count_files(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(Render, WritesNumberedFramesAtExactTimes) {
  TempDir dir;
  const Result r = springlab("render spring --frames 61 --size 320x180 --software --out " +
                             (dir / "f").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(count_files(dir / "f"), 61);
  const app::Image first = app::read_png(dir / "f" / "frame_00000.png");
  EXPECT_EQ(first.width, 320);
  EXPECT_EQ(first.height, 180);
  EXPECT_TRUE(fs::exists(dir / "f" / "frame_00060.png"));
  // Frame 60 at 60 frames a second is t = 1 s, exactly (dt = 1/120 divides 1/60).
  EXPECT_NE(r.out.find("t = 0 to 1 s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rendered 61 frames"), std::string::npos) << r.out;
}

TEST(Render, WritesAnH264Video) {
  if (std::system("command -v ffprobe > /dev/null") != 0)
    GTEST_SKIP() << "ffprobe (package ffmpeg) is missing";
  TempDir dir;
  const auto video = dir / "v.mp4";
  const Result r = springlab(
      "render cloth --frames 30 --fps 30 --size 320x180 --software --video " + video.string());
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_TRUE(fs::exists(video));
  EXPECT_EQ(count_files(dir.path), 1);  // no temporary file left
  const std::string probe =
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=codec_name,width,height,nb_read_frames,pix_fmt -of csv=p=0 '" +
      video.string() + "' > '" + (dir / "probe").string() + "'";
  ASSERT_EQ(std::system(probe.c_str()), 0);
  EXPECT_EQ(read_file(dir / "probe"), "h264,320,180,yuv420p,30\n");
}

// What render says is what it wrote: the frames and the times they show. In compare a lane that
// diverges is the lesson: said, each lane's verdict on stdout, exit 0 while a lane runs on; one
// lane that diverged is a render that could not show what was asked (exit 3, its reason on stderr).
TEST(Render, SaysTheFramesAndTimesItWroteAndWhichLaneDiverged) {
  TempDir dir;
  const std::string rope =
      "render rope --substeps 1 --dt 2e-4 --size 320x180 --software --select 60,300 ";
  const Result compared =
      springlab(rope + "--compare euler,symplectic-euler,rk4 --out " + (dir / "c").string());
  EXPECT_EQ(compared.status, 0) << compared.err;
  EXPECT_NE(compared.out.find(
                "rendered 2 frames of rope (320x180, 60 frames/s: frames 60 to 300, t = 1 to 5 s)"),
            std::string::npos)
      << compared.out;
  EXPECT_NE(compared.out.find("diverged   euler: diverged during step"), std::string::npos)
      << compared.out;
  EXPECT_NE(compared.out.find("Drawn from then on as it was at t = "), std::string::npos)
      << compared.out;
  EXPECT_EQ(compared.out.find("diverged   rk4"), std::string::npos) << compared.out;
  EXPECT_TRUE(fs::exists(dir / "c" / "frame_00300.png"));
  const Result alone = springlab(rope + "--method euler --out " + (dir / "a").string());
  EXPECT_EQ(alone.status, 3) << alone.out;
  EXPECT_NE(alone.err.find("springlab: rope: diverged during step"), std::string::npos)
      << alone.err;
  EXPECT_NE(alone.out.find("frames 60 to 300, t = 1 to 5 s"), std::string::npos) << alone.out;
}

TEST(Render, WithoutFfmpegVideoFailsAtOnceSayingHowToInstallIt) {
  TempDir dir;
  // Run with a PATH where there is no ffmpeg.
  const std::string command = "PATH=/nonexistent '" SPRINGLAB_EXECUTABLE
                              "' render spring --software --video '" +
                              (dir / "v.mp4").string() + "' > '" + (dir / "out").string() +
                              "' 2> '" + (dir / "err").string() + "'";
  const int raw = std::system(command.c_str());
  EXPECT_EQ(WEXITSTATUS(raw), 1);
  const std::string err = read_file(dir / "err");
  EXPECT_NE(err.find("needs ffmpeg"), std::string::npos) << err;
  EXPECT_NE(err.find("apt-get install ffmpeg"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir / "v.mp4"));
  for (const auto& e : fs::directory_iterator(dir.path))
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos);
}

TEST(Render, WithoutEglSaysWhatToInstall) {
  TempDir dir;
  const std::string command = "LIBGL_DRIVERS_PATH=/nonexistent '" SPRINGLAB_EXECUTABLE
                              "' render spring --software --frames 1 --out '" +
                              (dir / "f").string() + "' 2> '" + (dir / "err").string() +
                              "' > /dev/null";
  const int raw = std::system(command.c_str());
  EXPECT_EQ(WEXITSTATUS(raw), 1);
  const std::string err = read_file(dir / "err");
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_NE(err.find("apt-get install"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir / "f"));  // the folder it made is gone again
}

TEST(Render, BadOptionsExitTwoWithOneMessage) {
  TempDir dir;
  const std::string out = " --out " + (dir / "f").string();
  const std::pair<std::string, std::string> cases[] = {
      {"render spring", "exactly one of --out DIR"},
      {"render spring" + out + " --video x.mp4", "exactly one of --out DIR"},
      {"render spring --size 10x10" + out, "--size: must be WIDTHxHEIGHT"},
      {"render spring --size big" + out, "--size"},
      {"render spring --fps 0" + out, "--fps"},
      {"render spring --frames 0" + out, "--frames"},
      {"render spring --size 321x180 --video " + (dir / "v.mp4").string(), "even width and height"},
      {"render spring --frames 10 --select 10" + out,
       "--select: frame 10 is past the last frame (9)"},
      {"render spring --compare euler" + out, "--compare: give 2 to 4 methods"},
      {"render spring --compare euler,rk5" + out, "--compare: unknown method 'rk5'"},
      {"render spring --script nope.json" + out, "script 'nope.json': cannot be read"},
      {"render spring --out /proc/springlab/frames",
       "--out: cannot create the folder '/proc/springlab/frames'"},
      {"render spring --video /proc/springlab/v.mp4", "cannot write in folder '/proc/springlab'"},
      {"render nope" + out, "scene 'nope'"},
      {"render spring --compare verlet,rk4 --compare-layout side" + out,
       "--compare-layout: must be apart (a view each) or together (one view), got 'side'"},
  };
  for (const auto& [args, expected] : cases) {
    const Result r = springlab(args, dir.path);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << args << "\n" << r.err;
  }
  EXPECT_EQ(count_files(dir.path), 0);
}

TEST(Render, ScriptErrorsNameTheScriptAndTheField) {
  TempDir dir;
  const std::pair<std::string, std::string> cases[] = {
      {R"({"events": [{"t": 1, "grab": "rope:99"}]})",
       "/events/0/grab: must be an integer in [-16, 15], got 99"},
      {R"({"events": [{"t": 1, "grab": "cloth:0"}]})",
       "/events/0/grab: must be a particle index in [0, 15] or \"name:index\" with a generator of "
       "scene 'rope' (rope)"},
      {R"({"events": [{"t": -1, "release": true}]})", "/events/0/t: must be in [0, 1e+07], got -1"},
      {R"({"events": [{"t": 1, "set": {"method": "rk5"}}]})",
       "/events/0/set/method: must be a method name"},
      {R"({"events": [{"t": 1, "set": {"stiffness": 5}}]})",
       "/events/0/set/stiffness: unknown field"},
      {R"({"events": [{"t": 1, "grab": 3, "release": true}]})",
       "/events/0: must have exactly one action"},
      {R"({"events": [{"t": 1, "path": [[1, 0, 0, 0], [0.5, 1, 1, 1]]}]})",
       "/events/0/path/1/0: waypoint times must increase"},
      {R"({"events": []})", "/events: is required"},
      {"{", "not valid JSON"},
  };
  for (const auto& [text, expected] : cases) {
    write_file(dir / "s.json", text);
    const Result r =
        springlab("render rope --software --frames 1 --script s.json --out f", dir.path);
    EXPECT_EQ(r.status, 2) << text << "\n" << r.err;
    EXPECT_NE(r.err.find("script 's.json': "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << text << "\n" << r.err;
  }
}

// An interrupted render: what it had written as the signal was sent (each file and its size),
// how it ended (a status as waitpid gives it), and what it left.
struct Interrupted {
  std::vector<std::pair<fs::path, std::uintmax_t>> before;
  int status = 0;
  std::vector<fs::path> left;
};

std::vector<std::pair<fs::path, std::uintmax_t>> files_and_sizes(const fs::path& dir) {
  std::vector<std::pair<fs::path, std::uintmax_t>> files;
  std::error_code error;  // (a file may be renamed or removed while this looks)
  for (const auto& e : fs::directory_iterator(dir, error)) {
    const std::uintmax_t size = fs::file_size(e.path(), error);
    files.emplace_back(e.path(), error ? 0 : size);
  }
  return files;
}

// Starts a render, waits until it has written some bytes, lets it run a little longer,
// interrupts it, and says what it had written, how it ended and what it left.
Interrupted interrupt(const std::vector<std::string>& args, const fs::path& dir, int signal) {
  std::vector<const char*> argv{SPRINGLAB_EXECUTABLE};
  for (const auto& a : args) argv.push_back(a.c_str());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes,
                           POSIX_SPAWN_SETPGROUP);  // its own group, like a terminal job
  posix_spawnattr_setpgroup(&attributes, 0);
  EXPECT_EQ(
      posix_spawn(&pid, argv[0], &actions, &attributes, const_cast<char**>(argv.data()), environ),
      0);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  const auto written = [&] {
    for (const auto& [path, size] : files_and_sizes(dir))
      if (size > 0) return true;
    return false;
  };
  for (int k = 0; k < 500 && !written(); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  Interrupted r;
  r.before = files_and_sizes(dir);
  ::kill(-pid, signal);  // Ctrl-C reaches the whole group: springlab and its ffmpeg
  ::waitpid(pid, &r.status, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  for (const auto& e : fs::directory_iterator(dir)) r.left.push_back(e.path());
  return r;
}

// The signal ended it, as without a handler: it was still running when the signal came.
::testing::AssertionResult died_of(int status, int signal) {
  if (WIFSIGNALED(status) && WTERMSIG(status) == signal) return ::testing::AssertionSuccess();
  if (WIFEXITED(status))
    return ::testing::AssertionFailure()
           << "it had exited with status " << WEXITSTATUS(status) << " before the signal";
  return ::testing::AssertionFailure() << "wait status " << status;
}

TEST(Render, InterruptedVideoLeavesNothing) {
  // Without ffmpeg the render refuses --video at once (WithoutFfmpegVideoFailsAtOnce...): there
  // would be no encoding to interrupt, and an empty folder would prove nothing.
  if (std::system("command -v ffmpeg > /dev/null") != 0)
    GTEST_SKIP() << "ffmpeg is not installed (apt-get install ffmpeg), so no video is encoded and "
                    "there is no "
                    "encoding to interrupt";
  TempDir dir;
  const Interrupted r = interrupt({"render", "cloth", "--software", "--frames", "100000", "--size",
                                   "320x180", "--video", (dir / "v.mp4").string()},
                                  dir.path, SIGINT);
  // It was encoding when the signal came: ffmpeg had written part of the video, under a
  // temporary name beside v.mp4, and the signal is what ended springlab.
  ASSERT_EQ(r.before.size(), 1u) << "the render never started writing the video";
  EXPECT_NE(r.before[0].first.filename(), "v.mp4") << "the video was written under its final name";
  EXPECT_GT(r.before[0].second, 0u) << r.before[0].first << ": ffmpeg had encoded nothing";
  EXPECT_TRUE(died_of(r.status, SIGINT));
  // And nothing is left: not the temporary file, not v.mp4.
  EXPECT_TRUE(r.left.empty()) << r.left.front();
}

TEST(Render, InterruptedFramesLeaveOnlyWholeFrames) {
  TempDir dir;
  const Interrupted r = interrupt({"render", "cloth", "--software", "--frames", "100000", "--size",
                                   "320x180", "--out", dir.path.string()},
                                  dir.path, SIGTERM);
  EXPECT_TRUE(died_of(r.status, SIGTERM));
  EXPECT_FALSE(r.left.empty());
  for (const fs::path& p : r.left) {
    EXPECT_EQ(p.filename().string().rfind("frame_", 0), 0u) << p;  // no temporary file
    EXPECT_NO_THROW(app::read_png(p)) << p;                        // and every frame whole
  }
}

}  // namespace
}  // namespace springlab::test
