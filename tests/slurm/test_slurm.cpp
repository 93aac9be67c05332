// `tracer slurm` against a real one-node cluster (ci/slurm-up.sh, then `. /tmp/tracer-slurm/env`
// so that SLURM_CONF names its configuration). Without a reachable cluster every test is
// skipped with the reason. A path-traced scene split into 4 array tasks and merged equals the
// single render bit for bit, also after one task is cancelled while it renders and `slurm
// wait` resubmits its range; a merge over an incomplete set of parts fails and writes nothing.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <thread>

#include "test_util.h"

namespace tracer {
namespace {

namespace fs = std::filesystem;

const std::string kScene = std::string(TRACER_SOURCE_DIR) + "/scenes/cornell-box-path.json";
const std::string kOptions = " --spp 128 --width 128 --height 96";  // tasks of a few seconds

class Slurm : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::getenv("SLURM_CONF") || test::run_command("timeout 10 sinfo -h") != 0)
      GTEST_SKIP() << "no Slurm cluster: run ci/slurm-up.sh and source /tmp/tracer-slurm/env";
    dir_ = test::temp_dir("slurm");
    ASSERT_EQ(test::run_tracer("render " + kScene + kOptions + " --quiet -o " + path("single.exr")), 0);
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string submit(const std::string& extra) const {
    return "timeout 300 " + std::string(TRACER_BINARY) + " slurm submit " + kScene + kOptions + " --parts 4 --dir " +
           path("job") + " -o " + path("merged.exr") + extra;
  }
  int identical_to_single(const std::string& image) const {
    return test::run_tracer("compare " + image + " " + path("single.exr") + " --fail 0");
  }
  fs::path dir_;
};

TEST_F(Slurm, FourPartsMergeToTheSingleRenderBitForBit) {
  std::string output;
  ASSERT_EQ(test::run_command(submit(" --wait"), &output), 0) << output;
  EXPECT_EQ(identical_to_single(path("merged.exr")), 0);
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(fs::exists(path("job/part-" + std::to_string(i) + ".partial")));
}

TEST_F(Slurm, AKilledTaskIsRetriedAndTheImageIsStillIdentical) {
  std::string output;
  ASSERT_EQ(test::run_command(submit(""), &output), 0) << output;
  const size_t at = output.find("render array ");
  ASSERT_NE(at, std::string::npos) << output;
  const std::string array = output.substr(at + 13, output.find(' ', at + 13) - at - 13);
  std::string state;
  for (int i = 0; i < 600 && state.find("RUNNING") == std::string::npos; ++i) {
    test::run_command("squeue -h -j " + array + "_1 -o %T", &state);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_NE(state.find("RUNNING"), std::string::npos) << "task 1 never ran: " << state;
  ASSERT_EQ(test::run_command("scancel " + array + "_1"), 0);
  ASSERT_EQ(test::run_tracer("slurm wait " + path("job"), &output), 0) << output;
  EXPECT_NE(output.find("ranges missing after array " + array + ": 32:64 (task 1"), std::string::npos) << output;
  EXPECT_EQ(identical_to_single(path("merged.exr")), 0);
}

TEST_F(Slurm, AMergeOverIncompletePartsFailsAndWritesNothing) {
  std::string output;
  ASSERT_EQ(test::run_command(submit(" --wait"), &output), 0) << output;
  fs::remove(path("merged.exr"));
  fs::remove(path("job/part-2.partial"));
  // The merge job alone, as Slurm runs it: tracer merge refuses the missing part.
  EXPECT_NE(test::run_command("sbatch --wait --output=" + path("merge-again.log") + " " + path("job/merge.sh")), 0);
  EXPECT_FALSE(fs::exists(path("merged.exr")));
  std::string log;
  test::run_command("cat " + path("merge-again.log"), &log);
  EXPECT_NE(log.find("part-2.partial"), std::string::npos) << log;
  // The front end reports the missing range and, with no retries, does not merge.
  EXPECT_EQ(test::run_tracer("slurm wait " + path("job") + " --retries 0", &output), 2) << output;
  EXPECT_NE(output.find("64:96 (task 2"), std::string::npos) << output;
  EXPECT_FALSE(fs::exists(path("merged.exr")));
}

}  // namespace
}  // namespace tracer
