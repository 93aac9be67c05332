// Commands that remove or replace a directory touch only what they made themselves:
// `golden report --reset` clears only a directory holding its marker
// file, and gpu-pack stages in a directory of its own making instead of clearing
// DIR.partial-PID, which anyone could have made first.
#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <utility>

#include "io/new_directory.h"
#include "test_util.h"

namespace tracer {
namespace {

namespace fs = std::filesystem;

class DestructiveCommands : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::temp_dir("destructive"); }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(DestructiveCommands, ReportResetRefusesADirectoryItDidNotMake) {
  const fs::path mine = dir_ / "thesis";
  fs::create_directories(mine / "chapters");
  std::ofstream(mine / "chapters" / "one.tex") << "years of work";
  std::string out;
  EXPECT_EQ(test::run_tracer("golden report --reset --report " + mine.string(), &out), 2) << out;
  EXPECT_NE(out.find(mine.string() + ": not removed"), std::string::npos) << out;
  EXPECT_EQ(test::read_file(mine / "chapters" / "one.tex"), "years of work");
}

TEST_F(DestructiveCommands, ReportResetRefusesASymbolicLinkAndAFile) {
  const fs::path target = dir_ / "target";
  fs::create_directories(target);
  std::ofstream(target / "keep.txt") << "keep";
  fs::create_directory_symlink(target, dir_ / "link");
  std::string out;
  EXPECT_EQ(test::run_tracer("golden report --reset --report " + (dir_ / "link").string(), &out), 2) << out;
  EXPECT_EQ(test::read_file(target / "keep.txt"), "keep");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link"));
  std::ofstream(dir_ / "file.txt") << "a file";
  EXPECT_EQ(test::run_tracer("golden report --reset --report " + (dir_ / "file.txt").string(), &out), 2) << out;
  EXPECT_EQ(test::read_file(dir_ / "file.txt"), "a file");
}

TEST_F(DestructiveCommands, ReportResetClearsAReportItMade) {
  const fs::path report = dir_ / "report";
  ASSERT_EQ(test::run_tracer("golden report --reset --report " + report.string()), 0);
  ASSERT_TRUE(fs::is_regular_file(report / ".tracer-golden-report"));
  std::ofstream(report / "rows" / "old.json") << "{}";
  fs::create_directories(report / "old");
  std::string out;
  ASSERT_EQ(test::run_tracer("golden report --reset --report " + report.string(), &out), 0) << out;
  EXPECT_FALSE(fs::exists(report / "rows" / "old.json"));
  EXPECT_FALSE(fs::exists(report / "old"));
  EXPECT_TRUE(fs::is_regular_file(report / ".tracer-golden-report"));
  fs::create_directories(dir_ / "empty");  // an empty directory is adopted
  EXPECT_EQ(test::run_tracer("golden report --reset --report " + (dir_ / "empty").string()), 0);
  // A report assembled where none was (the fixture's cleanup after a failed reset) is marked too.
  ASSERT_EQ(test::run_tracer("golden report --report " + (dir_ / "assembled").string()), 0);
  EXPECT_EQ(test::run_tracer("golden report --reset --report " + (dir_ / "assembled").string(), &out), 0) << out;
}

// gpu-pack used to remove_all(OUT.partial-PID) before staging there: a directory of that name
// (PID known to whoever starts the command, or guessed) was deleted. The shell's PID becomes
// the tracer's through exec; the pack then fails at its manifest, after the staging began.
TEST_F(DestructiveCommands, GpuPackNeverRemovesADirectoryItDidNotMake) {
  const fs::path out = dir_ / "pack", empty_root = dir_ / "root";
  fs::create_directories(empty_root);
  const std::string script = "sh -c 'echo $$ > " + (dir_ / "pid").string() + "; mkdir " + out.string() +
                             ".partial-$$ && echo keep > " + out.string() + ".partial-$$/keep.txt && exec " +
                             TRACER_BINARY + " gpu-pack " + out.string() + " --root " + empty_root.string() +
                             " --runner " + TRACER_BINARY + "'";  // sh -c: $$ is the PID exec hands on
  std::string output;
  EXPECT_EQ(test::run_command(script, &output), 2) << output;
  const std::string pid = test::read_file(dir_ / "pid").substr(0, test::read_file(dir_ / "pid").find('\n'));
  EXPECT_EQ(test::read_file(out.string() + ".partial-" + pid + "/keep.txt"), "keep\n");
  EXPECT_FALSE(fs::exists(out));
  size_t entries = 0;  // root, pid, the planted directory: no staging directory left behind
  for (const auto& e : fs::directory_iterator(dir_)) entries += e.exists() ? 1 : 0;
  EXPECT_EQ(entries, 3u);
}

// SIGINT, SIGTERM or SIGHUP during gpu-pack (strace sends it at the third file's rename, with
// the staging directory half full) end the command by that signal with the staging directory
// removed; it used to stay behind (io/interrupt.h).
TEST_F(DestructiveCommands, AnInterruptedGpuPackLeavesNoStagingDirectory) {
  if (test::run_command("strace -f -qq -o /dev/null true") != 0)
    GTEST_SKIP() << "strace cannot trace here (no strace, or ptrace refused)";
  for (const auto& [name, number] : {std::pair{"INT", SIGINT}, {"TERM", SIGTERM}, {"HUP", SIGHUP}}) {
    const fs::path out = dir_ / name / "pack";
    fs::create_directories(out.parent_path());
    std::string output;
    const int status = test::run_command(
        std::string("strace -f -qq -o /dev/null -e trace=rename,renameat,renameat2 -e inject=rename,renameat,") +
            "renameat2:signal=" + name + ":when=3 " + TRACER_BINARY + " gpu-pack " + out.string() + " --root " +
            TRACER_SOURCE_DIR,
        &output);
    EXPECT_EQ(status, 128 + number) << name << "\n" << output;
    EXPECT_NE(output.find("interrupted by"), std::string::npos) << output;
    EXPECT_TRUE(fs::is_empty(out.parent_path())) << name << ": something was left in " << out.parent_path();
  }
}

TEST_F(DestructiveCommands, NewDirectoriesAreNewAndDistinct) {
  const fs::path a = make_new_directory(dir_, "stage-"), b = make_new_directory(dir_, "stage-");
  EXPECT_NE(a, b);
  EXPECT_TRUE(fs::is_directory(a) && fs::is_empty(a));
  EXPECT_THROW(make_new_directory(dir_ / "missing", "stage-"), std::exception);
}

}  // namespace
}  // namespace tracer
