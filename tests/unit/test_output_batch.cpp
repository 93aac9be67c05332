// OutputBatch (io/output_batch.h): the files of a batch land together on commit, and a batch
// that fails, is abandoned or is interrupted by SIGTERM leaves the earlier files as they were
// and no temporary behind. The full-disk cases of every command: test_full_disk.cpp.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>

#include "io/input_error.h"
#include "io/output_batch.h"
#include "test_util.h"

namespace tracer {
namespace {

namespace fs = std::filesystem;

size_t entries(const fs::path& dir) { return std::distance(fs::directory_iterator(dir), fs::directory_iterator()); }

class OutputBatchTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::temp_dir("output-batch");
    std::ofstream(dir_ / "a.txt") << "earlier a";
    std::ofstream(dir_ / "b.txt") << "earlier b";
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const char* name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(OutputBatchTest, CommitReplacesEveryFileAndLeavesNoTemporary) {
  OutputBatch batch;
  batch.add(path("a.txt"), "new a");
  batch.add(path("b.txt"), "new b");
  EXPECT_EQ(test::read_file(dir_ / "a.txt"), "earlier a");  // nothing lands before the commit
  batch.commit();
  EXPECT_EQ(test::read_file(dir_ / "a.txt"), "new a");
  EXPECT_EQ(test::read_file(dir_ / "b.txt"), "new b");
  EXPECT_EQ(entries(dir_), 2u);
}

TEST_F(OutputBatchTest, AFailedFileLeavesEveryEarlierFile) {
  {
    OutputBatch batch;
    batch.add(path("a.txt"), "new a");
    EXPECT_THROW(batch.add(path("missing-dir/b.txt"), "new b"), InputError);
  }
  EXPECT_EQ(test::read_file(dir_ / "a.txt"), "earlier a");
  EXPECT_EQ(test::read_file(dir_ / "b.txt"), "earlier b");
  EXPECT_EQ(entries(dir_), 2u);
}

TEST_F(OutputBatchTest, ADirectoryIsRefusedBeforeAnythingLands) {
  fs::create_directories(dir_ / "d");
  OutputBatch batch;
  batch.add(path("a.txt"), "new a");
  EXPECT_THROW(batch.add(path("d"), "new d"), InputError);
  EXPECT_EQ(test::read_file(dir_ / "a.txt"), "earlier a");
}

// Run as root, a batch renamed its temporary over a device or FIFO it was given (a render's
// --stats /dev/null replaced /dev/null with a regular file). A FIFO stands in for the device.
TEST_F(OutputBatchTest, ADeviceOrFifoIsNeverReplaced) {
  ASSERT_EQ(::mkfifo(path("pipe").c_str(), 0600), 0);
  OutputBatch batch;
  EXPECT_THROW(batch.add(path("pipe"), "new pipe"), InputError);
  EXPECT_TRUE(fs::is_fifo(dir_ / "pipe"));
  fs::create_symlink(dir_ / "pipe", dir_ / "link");  // a symlink is replaced, not what it names
  batch.add(path("link"), "new link");
  batch.commit();
  EXPECT_TRUE(fs::is_fifo(dir_ / "pipe"));
  EXPECT_EQ(test::read_file(dir_ / "link"), "new link");
}

TEST_F(OutputBatchTest, ATargetNamedTwiceIsRefused) {
  OutputBatch batch;
  batch.add(path("a.txt"), "one");
  EXPECT_THROW(batch.add(path("a.txt"), "two"), InputError);
}

// A child process adds a file and is killed by SIGTERM before committing: the handler removes
// the temporary, and the process still ends by the signal.
TEST_F(OutputBatchTest, SigtermBeforeCommitRemovesTheTemporaries) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    OutputBatch batch;
    batch.add(path("a.txt"), "new a");
    std::raise(SIGTERM);
    ::_exit(0);  // not reached
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
  EXPECT_EQ(test::read_file(dir_ / "a.txt"), "earlier a");
  EXPECT_EQ(entries(dir_), 2u);
}

// A child commits a journaled batch and SIGKILL stops it after each step: before the journal
// lands nothing changed; after, finish_interrupted_commit makes every file new.
TEST_F(OutputBatchTest, AJournaledCommitKilledAtAnyStepIsAllOldOrAllNew) {
  const std::string journal = path(".journal");
  for (int kill_at = -1; kill_at <= 3; ++kill_at) {  // -1: before the commit; 3: after the journal is gone
    std::ofstream(dir_ / "a.txt") << "earlier a";
    std::ofstream(dir_ / "b.txt") << "earlier b";
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      OutputBatch batch;
      batch.add(path("a.txt"), "new a");
      batch.add(path("b.txt"), "new b");
      if (kill_at < 0) std::raise(SIGKILL);
      batch.commit(journal, [&](size_t step) {
        if (static_cast<int>(step) == kill_at) std::raise(SIGKILL);
      });
      ::_exit(0);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << kill_at;
    EXPECT_EQ(finish_interrupted_commit(journal), kill_at >= 0 && kill_at < 3) << kill_at;
    remove_orphan_temporaries(dir_.string());
    const std::string a = test::read_file(dir_ / "a.txt"), b = test::read_file(dir_ / "b.txt");
    EXPECT_EQ(a, kill_at < 0 ? "earlier a" : "new a") << kill_at;
    EXPECT_EQ(b, kill_at < 0 ? "earlier b" : "new b") << kill_at;
    EXPECT_EQ(entries(dir_), 2u) << kill_at;
  }
}

// The journal is input: it may rename only tracer temporaries onto names in its own directory.
TEST_F(OutputBatchTest, AJournalNamingAnythingElseIsRefusedAndChangesNothing) {
  std::ofstream(dir_ / ".tracer-0123456789abcdef.tmp") << "temporary";
  for (const std::string line : {"a.txt\tb.txt", ".tracer-0123456789abcdef.tmp\t../b.txt",
                                 ".tracer-0123456789abcdef.tmp\t", "../.tracer-0123456789abcdef.tmp\ta.txt"}) {
    std::ofstream(dir_ / ".journal") << "tracer-commit-journal/1\n" << line << "\n";
    EXPECT_THROW(finish_interrupted_commit(path(".journal")), InputError) << line;
    EXPECT_EQ(test::read_file(dir_ / "a.txt"), "earlier a");
    EXPECT_EQ(test::read_file(dir_ / "b.txt"), "earlier b");
    EXPECT_EQ(test::read_file(dir_ / ".tracer-0123456789abcdef.tmp"), "temporary");
  }
  std::ofstream(dir_ / ".journal") << "not a journal\n";
  EXPECT_THROW(finish_interrupted_commit(path(".journal")), InputError);
}

// SIGTERM between the renames of a render's image and its --stats file removed the stats
// temporary and left a new image beside old stats; now the signal waits for the last rename.
// strace's fault injection delivers it at the first rename of the real binary.
TEST_F(OutputBatchTest, SigtermDuringTheRenamesWaitsForTheLast) {
  if (test::run_command("strace -f -qq -o /dev/null true") != 0) {
    GTEST_SKIP() << "strace cannot trace here (no strace, or ptrace refused)";
  }
  const std::string scene = std::string(TRACER_SOURCE_DIR) + "/scenes/cornell-box.json";
  std::ofstream(dir_ / "out.png") << "earlier image";
  std::ofstream(dir_ / "stats.json") << "earlier stats";
  std::string output;
  test::run_command(
      "strace -f -qq -o /dev/null -e trace=rename,renameat,renameat2 -e inject=rename,renameat,"
      "renameat2:signal=TERM:when=1 " +
          std::string(TRACER_BINARY) + " render " + scene + " --quiet --width 8 --height 6 --spp 1 -o " +
          path("out.png") + " --stats " + path("stats.json"),
      &output);
  EXPECT_NE(test::read_file(dir_ / "out.png"), "earlier image") << output;
  EXPECT_NE(test::read_file(dir_ / "stats.json"), "earlier stats") << output;
  EXPECT_EQ(entries(dir_), 4u) << output;  // a, b, the image and the stats; no temporary
}

// The temporary's name was .STEM.tmpPID.EXT, opened with O_TRUNC: anyone who could write to
// the directory could plant a symlink there and have the next render overwrite its target.
TEST_F(OutputBatchTest, ASymlinkPlantedAtTheOldTemporaryNameIsNeverFollowed) {
  const fs::path victim = dir_ / "victim.txt";
  std::ofstream(victim) << "precious";
  fs::create_symlink(victim, dir_ / (".out.tmp" + std::to_string(::getpid()) + ".txt"));
  write_file_atomically(path("out.txt"), "new out");
  EXPECT_EQ(test::read_file(victim), "precious");
  EXPECT_EQ(test::read_file(dir_ / "out.txt"), "new out");
  EXPECT_EQ(entries(dir_), 5u);  // a, b, victim, the planted link, out
}

// A 255-byte name is legal; the old temporary's name (the stem plus ".tmpPID") was not.
TEST_F(OutputBatchTest, AnOutputNameOfTheLongestLegalLengthIsWritten) {
  const std::string name = std::string(251, 'n') + ".txt";
  write_file_atomically((dir_ / name).string(), "long");
  EXPECT_EQ(test::read_file(dir_ / name), "long");
  EXPECT_EQ(entries(dir_), 3u);
}

TEST_F(OutputBatchTest, TemporariesHaveUnpredictableNamesAndAreNewFiles) {
  OutputBatch first, second;
  first.add(path("a.txt"), "first");
  second.add(path("a.txt"), "second");  // two batches on one target: two distinct temporaries
  std::vector<std::string> temporaries;
  for (const auto& e : fs::directory_iterator(dir_))
    if (e.path().filename().string().rfind(".tracer-", 0) == 0) temporaries.push_back(e.path().filename().string());
  ASSERT_EQ(temporaries.size(), 2u);
  EXPECT_NE(temporaries[0], temporaries[1]);
  second.commit();
  first.commit();
  EXPECT_EQ(test::read_file(dir_ / "a.txt"), "first");
  EXPECT_EQ(entries(dir_), 2u);
}

}  // namespace
}  // namespace tracer
