// Homework 8 checked (springlab homework check), on solutions as students write them: every file in
// tests/homework/ropes/ (a correct rope with one mistake planted a file, rope_with.hpp) and
// tests/homework/students/ (whole solutions in the styles students publish: GAMES101's and CS
// 184's, float and double, every damping form, their own headers, the usual slips) says in its
// "expect" lines what a careful reader finds:
//   // expect: pass                  exit 0, no check failed
//   // expect: fail KEY KEY ...      exit 1, the failed lines' keys exactly these, in order (each
//                                    mistake named, and nothing else)
//   // expect: exit 2                bad input (a file that does not compile)
//   // expect-euler: ROW | constraints | none     what simulateEuler was found to be
//   // expect-verlet: ...                          and simulateVerlet
//   // expect-says: TEXT             a line of the report says this
//   // expect-err: TEXT              standard error says this
//   // expect-options: OPTIONS       given to the command
// and this test holds the checker to each (the report read as JSON, by its keys). Beside them: the
// starter kit, the report in Chinese, the headers that change what the checker calls.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "cli/cli_support.hpp"

namespace springlab::test {
namespace {

namespace fs = std::filesystem;
const fs::path kHomework = fs::path(SPRINGLAB_SOURCE_DIR) / "tests" / "homework";

struct Expectation {
  fs::path path;     // a rope.cpp, or a folder holding one
  std::string name;  // for GoogleTest
  int exit = 0;
  std::vector<std::string> failed;
  std::string euler, verlet, options;
  std::vector<std::string> says, err;
};

// Named by its path in a failure's message, not dumped as bytes.
void PrintTo(const Expectation& e, std::ostream* os) {
  *os << e.path.string();
}

Expectation read_expectation(const fs::path& path) {
  Expectation e;
  e.path = path;
  const fs::path file = fs::is_directory(path) ? path / "rope.cpp" : path;
  e.name = path.parent_path().filename().string() + "_" + path.stem().string();
  for (char& c : e.name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    auto value = [&](const std::string& key) -> std::optional<std::string> {
      const std::string tag = "// " + key + ": ";
      if (line.rfind(tag, 0) != 0) return std::nullopt;
      return line.substr(tag.size());
    };
    if (auto v = value("expect")) {
      std::istringstream words(*v);
      std::string kind;
      words >> kind;
      if (kind == "pass")
        e.exit = 0;
      else if (kind == "exit")
        words >> e.exit;
      else {
        e.exit = 1;
        for (std::string key; words >> key;) e.failed.push_back(key);
      }
    }
    if (auto v = value("expect-euler")) e.euler = *v;
    if (auto v = value("expect-verlet")) e.verlet = *v;
    if (auto v = value("expect-says")) e.says.push_back(*v);
    if (auto v = value("expect-err")) e.err.push_back(*v);
    if (auto v = value("expect-options")) e.options = " " + *v;
  }
  return e;
}

std::vector<Expectation> every_solution() {
  std::vector<Expectation> all;
  for (const char* folder : {"ropes", "students"}) {
    std::vector<fs::path> paths;
    for (const auto& entry : fs::directory_iterator(kHomework / folder))
      if (entry.path().extension() == ".cpp" || fs::is_regular_file(entry.path() / "rope.cpp"))
        paths.push_back(entry.path());
    std::sort(paths.begin(), paths.end());
    for (const fs::path& p : paths) all.push_back(read_expectation(p));
  }
  return all;
}

Result check(const std::string& path, const std::string& options = "") {
  return springlab("homework check '" + path + "' --lang en" + options);
}

// What a step was found to be, as the expectations name it.
std::string found(const nlohmann::json& step) {
  if (step["constraints"].get<bool>()) return "constraints";
  return step["method"].is_null() ? "none" : step["method"].get<std::string>();
}

class Solutions : public testing::TestWithParam<Expectation> {};

TEST_P(Solutions, AreClassifiedAsACarefulReaderWould) {
  const Expectation& e = GetParam();
  const Result r = check(e.path.string(), " --json" + e.options);
  ASSERT_EQ(r.status, e.exit) << r.out << r.err;
  for (const std::string& text : e.err)
    EXPECT_NE(r.err.find(text), std::string::npos) << text << "\n" << r.err;
  if (e.exit == 2) {
    // The same sentence on standard output, as JSON, for a grader that reads only that.
    const nlohmann::json bad = nlohmann::json::parse(r.out);
    EXPECT_TRUE(bad["bad_input"].get<bool>());
    EXPECT_EQ("springlab: " + bad["error"].get<std::string>() + "\n", r.err);
    return;
  }
  const nlohmann::json report = nlohmann::json::parse(r.out);
  std::vector<std::string> failed;
  std::string lines;
  for (const auto& section : report["sections"])
    for (const auto& line : section["lines"]) {
      lines += line["kind"].get<std::string>() + " [" + line["key"].get<std::string>() + "] " +
               line["text"].get<std::string>() + "\n";
      if (line["kind"] == "fail") failed.push_back(line["key"]);
    }
  EXPECT_EQ(failed, e.failed) << lines;
  EXPECT_EQ(report["failed"].get<int>(), static_cast<int>(e.failed.size()));
  if (!e.euler.empty()) {
    EXPECT_EQ(found(report["steps"]["simulateEuler"]), e.euler) << lines;
  }
  if (!e.verlet.empty()) {
    EXPECT_EQ(found(report["steps"]["simulateVerlet"]), e.verlet) << lines;
  }
  for (const std::string& text : e.says)
    EXPECT_NE(lines.find(text), std::string::npos) << text << "\n" << lines;
}

INSTANTIATE_TEST_SUITE_P(Homework, Solutions, testing::ValuesIn(every_solution()),
                         [](const testing::TestParamInfo<Expectation>& info) {
                           return info.param.name;
                         });

// The corpus holds what the issue asks of it: at least 15 correct solutions and a file a mistake.
TEST(Homework, TheCorpusHasFifteenCorrectSolutionsAndAFileAMistake) {
  int correct = 0;
  std::set<std::string> mistakes;
  for (const Expectation& e : every_solution()) {
    if (e.exit == 0) ++correct;
    mistakes.insert(e.failed.begin(), e.failed.end());
  }
  EXPECT_GE(correct, 15);
  for (const char* key :
       {"accel-twice", "gravity-no-mass", "gravity-times-step", "spacing-n", "reversed",
        "spring-not-in-rope", "pins-before-masses", "no-gravity", "nothing-built", "forces-kept",
        "damping-sign", "verlet-a-h", "velocity-not-stored", "spring-no-mass", "forces-assigned",
        "verlet-half", "last-overwritten"})
    EXPECT_TRUE(mistakes.count(key)) << key;
}

// The text report is the JSON's lines, with a heading that says which headers were used.
TEST(Homework, TheTextReportSaysWhatWasCompiledAndCountsTheChecks) {
  const Result r = check((kHomework / "students" / "own_headers").string());
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("own_headers/rope.cpp, with your rope.h, mass.h and spring.h (the "
                       "exercise's for the rest)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\n  ok    simulateEuler is Symplectic Euler"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" 0 failed.\n"), std::string::npos) << r.out;
}

// The report in the student's language: every line Chinese, the numbers kept.
TEST(Homework, TheReportSpeaksChinese) {
  const Result r = springlab("homework check '" + (kHomework / "ropes" / "uneven.cpp").string() +
                             "' --lang zh-CN");
  ASSERT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("7.031"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("evenly spaced"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("checks passed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("项检查通过"), std::string::npos) << r.out;
}

// The starter kit compiles as shipped, and the checker says where to start; the kit never writes
// over a student's work.
TEST(Homework, TheStarterKitSaysWhereToStart) {
  TempDir dir;
  const Result kit = springlab("homework kit " + (dir / "hw8").string());
  ASSERT_EQ(kit.status, 0) << kit.err;
  const Result r = check((dir / "hw8").string(), " --json");
  ASSERT_EQ(r.status, 1) << r.out << r.err;
  const nlohmann::json report = nlohmann::json::parse(r.out);
  std::vector<std::string> failed;
  for (const auto& section : report["sections"])
    for (const auto& line : section["lines"])
      if (line["kind"] == "fail") failed.push_back(line["key"]);
  EXPECT_EQ(failed, (std::vector<std::string>{"nothing-built", "not-written", "not-written"}))
      << r.out;
  EXPECT_NE(r.out.find("Start there (Part 1)"), std::string::npos) << r.out;
  const Result again = springlab("homework kit " + (dir / "hw8").string());
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.err.find("exists already"), std::string::npos) << again.err;
}

// A rope.h of the student's that changes what the checker calls: one sentence naming the
// difference and what the exercise declares; a step declared but never written: which one.
TEST(Homework, HeadersThatChangeWhatTheCheckerCallsAreSaid) {
  TempDir dir;
  const std::string rope_h =
      read_file(fs::path(SPRINGLAB_SOURCE_DIR) / "assets" / "homework" / "include" / "rope.h");
  std::string changed = rope_h;
  changed.replace(changed.find("void simulateEuler(float delta_t, Vector2D gravity);"),
                  std::string("void simulateEuler(float delta_t, Vector2D gravity);").size(),
                  "void simulateEuler(float delta_t, Vector2D gravity, double damping);");
  write_file(dir / "rope.h", changed);
  std::string source = read_file(kHomework / "students" / "games101_typical.cpp");
  source.replace(source.find("void Rope::simulateEuler(float delta_t, Vector2D gravity)"),
                 std::string("void Rope::simulateEuler(float delta_t, Vector2D gravity)").size(),
                 "void Rope::simulateEuler(float delta_t, Vector2D gravity, double)");
  write_file(dir / "rope.cpp", source);
  const Result r = check(dir.path.string());
  EXPECT_EQ(r.status, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("compiles, but the checker cannot call it through your rope.h"),
            std::string::npos)
      << r.err;
  EXPECT_NE(
      r.err.find("The exercise declares void simulateEuler(float delta_t, Vector2D gravity)."),
      std::string::npos)
      << r.err;

  write_file(dir / "rope.h", rope_h);
  source = read_file(kHomework / "students" / "games101_typical.cpp");
  source = source.substr(0, source.find("    void Rope::simulateVerlet")) + "}\n";
  write_file(dir / "rope.cpp", source);
  const Result missing = check(dir.path.string());
  EXPECT_EQ(missing.status, 2) << missing.out << missing.err;
  EXPECT_NE(missing.err.find("does not define what the checker calls"), std::string::npos)
      << missing.err;
  EXPECT_NE(missing.err.find("simulateVerlet"), std::string::npos) << missing.err;
}

// A step that starts a process of its own (one that ignores every signal it can) does not leave
// it running: the runner's whole process group ends with it.
TEST(Homework, NothingAStepStartsOutlivesTheCheck) {
  TempDir dir;
  const fs::path pids = dir / "pids";
  std::string source = read_file(kHomework / "students" / "games101_typical.cpp");
  const size_t verlet = source.find("void Rope::simulateVerlet(float delta_t, Vector2D gravity)");
  ASSERT_NE(verlet, std::string::npos);
  source.insert(source.find('{', verlet) + 1,
                "\n  static bool forked = false;\n"
                "  if (!forked && (forked = true) && fork() == 0) {\n"
                "    sigset_t all;\n    sigfillset(&all);\n"
                "    sigprocmask(SIG_BLOCK, &all, nullptr);\n"
                "    FILE* f = std::fopen(\"" +
                    pids.string() +
                    "\", \"a\");\n"
                    "    std::fprintf(f, \"%d\\n\", int(getpid()));\n    std::fclose(f);\n"
                    "    sleep(60);\n    _exit(0);\n  }\n");
  write_file(dir / "rope.cpp",
             "#include <csignal>\n#include <cstdio>\n#include <unistd.h>\n" + source);
  const Result r = check(dir.path.string());
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  std::ifstream in(pids);
  int count = 0;
  for (int pid; in >> pid; ++count) {
    // Gone, or a zombie waiting for its new parent: SIGKILL is sent, not waited for.
    const fs::path stat = "/proc/" + std::to_string(pid) + "/stat";
    bool running = true;
    for (int tries = 0; tries < 100 && running; ++tries) {
      const std::string text = fs::exists(stat) ? read_file(stat) : "";
      running = !text.empty() && text.find(") Z") == std::string::npos;
      if (running) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    EXPECT_FALSE(running) << "process " << pid << " started by simulateVerlet still runs";
  }
  EXPECT_GE(count, 1) << "the step's fork() did not run";
}

// A header given for rope.cpp, and a folder with two different rope.cpp: said, not guessed.
TEST(Homework, AHeaderOrTwoRopesAreBadInput) {
  TempDir dir;
  fs::create_directory(dir / "header");
  write_file(dir / "header" / "rope.h", "#pragma once\n");
  const Result header = check((dir / "header" / "rope.h").string());
  EXPECT_EQ(header.status, 2);
  EXPECT_NE(header.err.find("rope.h is a header: give your rope.cpp"), std::string::npos)
      << header.err;
  const std::string source = read_file(kHomework / "students" / "games101_typical.cpp");
  write_file(dir / "rope.cpp", source);
  fs::create_directory(dir / "src");
  write_file(dir / "src" / "rope.cpp", source + "\n// a later version\n");
  const Result two = check(dir.path.string());
  EXPECT_EQ(two.status, 2);
  EXPECT_NE(two.err.find("two different rope.cpp"), std::string::npos) << two.err;
  write_file(dir / "src" / "rope.cpp", source);  // a copy: either is the work
  EXPECT_EQ(check(dir.path.string()).status, 0);
}

TEST(Homework, AMissingFileOrFolderIsBadInput) {
  const Result missing = springlab("homework check no-such-rope.cpp");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("cannot read no-such-rope.cpp: no such file"), std::string::npos)
      << missing.err;
  TempDir empty;
  const Result none = springlab("homework check " + empty.path.string());
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("no rope.cpp in"), std::string::npos) << none.err;
}

}  // namespace
}  // namespace springlab::test
