// Every writer on a full disk: a small tmpfs is mounted in a private mount namespace
// (`unshare -m`, or `unshare -rm` without root), filled, and a command that writes into it
// must exit 2 naming the file it could not write, leave every earlier file byte for byte as
// it was, and leave no temporary behind. Skipped, with the reason, where no tmpfs can be
// mounted. Commands writing more than 8 KiB run a second round with 8 KiB free, so that their
// writes start and fail half-way.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "golden_sandbox.h"
#include "test_util.h"

namespace tracer {
namespace {

namespace fs = std::filesystem;

constexpr const char* kScene =
    R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 3], "to": [0, 0, 0], "vfov": 40},
  "film": {"width": 64, "height": 48}, "render": {"integrator": "path", "spp": 2},
  "background": {"type": "constant", "radiance": [0.5, 0.6, 0.7]},
  "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.3, 0.2]}},
  "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})";

// Every file under dir with its bytes.
std::map<std::string, std::string> files_under(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = test::read_file(e.path());
  return files;
}

class FullDisk : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::temp_dir("full-disk");
    fs::create_directories(dir_ / "in");
    fs::create_directories(dir_ / "earlier");
    std::ofstream(dir_ / "in/s.json") << kScene;
    const std::string scene = (dir_ / "in/s.json").string();
    // The earlier outputs every command below would replace, made while the disk had room.
    ASSERT_EQ(tracer("render " + scene + " --quiet -o " + earlier("out.exr") + " --stats " + earlier("stats.json")), 0);
    ASSERT_EQ(tracer("render " + scene + " --quiet -o " + earlier("out.png")), 0);
    ASSERT_EQ(tracer("render " + scene + " --quiet --samples 0:1 -o " + earlier("part.partial")), 0);
    ASSERT_EQ(tracer("render " + scene + " --quiet --samples 1:2 -o " + earlier("rest.partial")), 0);
    ASSERT_EQ(tracer("generate cube -o " + earlier("mesh.obj")), 0);
    ASSERT_EQ(tracer("bundle " + scene + " -o " + earlier("s.bundle")), 0);
    ASSERT_EQ(tracer("render " + scene + " --quiet --seed 9 -o " + (dir_ / "in/other.exr").string()), 0);
    std::ofstream(dir_ / "earlier/converge.csv") << "an earlier table\n";
    std::ofstream(dir_ / "earlier/converge.png") << "an earlier plot\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  int tracer(const std::string& args) { return test::run_tracer(args); }
  std::string earlier(const std::string& name) const { return (dir_ / "earlier" / name).string(); }

  // Runs `args` (DISK stands for the mounted directory) on a tmpfs holding a copy of earlier/
  // (and of a golden root, `golden/`), filled up to `free_kib` KiB. Returns the exit code; 77
  // when no tmpfs can be mounted. After the command, the disk's files are copied to after/.
  int run_on_full_disk(const std::string& args, int free_kib, std::string& output) {
    fs::remove_all(dir_ / "disk");
    fs::remove_all(dir_ / "after");
    fs::create_directories(dir_ / "disk");
    const fs::path script = dir_ / "full-disk.sh";
    std::ofstream(script) << "set -u\n"
                          << "cd " << dir_ << "\n"
                          << "mount -t tmpfs -o size=4m tmpfs disk 2>/dev/null || exit 77\n"
                          << "cp -r earlier/. disk/\n"
                          << "head -c 8M /dev/zero > disk/.fill 2>/dev/null\n"
                          << "truncate -s -" << free_kib << "K disk/.fill\n"
                          << "timeout 60 " << TRACER_BINARY << " " << args << " > output.log 2>&1\n"
                          << "status=$?\n"
                          << "rm disk/.fill\n"
                          << "cp -r disk after\n"
                          << "exit $status\n";
    const char* unshare = test::run_command("unshare -m true") == 0    ? "unshare -m"
                          : test::run_command("unshare -rm true") == 0 ? "unshare -rm"
                                                                       : nullptr;
    if (!unshare) return 77;
    const int status = test::run_command(std::string(unshare) + " bash " + script.string());
    output = test::read_file(dir_ / "output.log");
    return status;
  }

  // DISK in a command stands for the mounted directory.
  std::string on_disk(std::string text) const {
    for (size_t at; (at = text.find("DISK")) != std::string::npos;) text.replace(at, 4, (dir_ / "disk").string());
    return text;
  }

  // The command failed cleanly: exit 2, `target` named with "cannot write", every earlier
  // file as it was, nothing new.
  void expect_clean_failure(const std::string& command, const std::string& target_text,
                            std::initializer_list<int> free_kibs = {0}) {
    const std::string args = on_disk(command), target = on_disk(target_text);
    for (const int free_kib : free_kibs) {
      std::string output;
      const int status = run_on_full_disk(args, free_kib, output);
      if (status == 77) GTEST_SKIP() << "no tmpfs can be mounted here (unshare -m and unshare -rm failed)";
      SCOPED_TRACE(args + " with " + std::to_string(free_kib) + " KiB free");
      EXPECT_EQ(status, 2) << output;
      EXPECT_NE(output.find("cannot write"), std::string::npos) << output;
      EXPECT_NE(output.find("No space left on device"), std::string::npos) << output;
      EXPECT_NE(output.find(target), std::string::npos) << output;
      EXPECT_EQ(output.find("wrote "), std::string::npos) << output;
      const auto before = files_under(dir_ / "earlier"), after = files_under(dir_ / "after");
      for (const auto& [name, bytes] : before) EXPECT_TRUE(after.count(name) && after.at(name) == bytes) << name;
      for (const auto& [name, bytes] : after) EXPECT_TRUE(before.count(name)) << "left behind: " << name;
    }
  }

  fs::path dir_;
};

TEST_F(FullDisk, RenderKeepsTheEarlierImage) {
  expect_clean_failure("render " + (dir_ / "in/s.json").string() + " --quiet --width 512 --height 512 -o DISK/out.exr",
                       "out.exr", {0, 8});
}

// The image goes to a disk with room and is written first; the stats file then fails on the
// full disk, and the earlier image must still be there.
TEST_F(FullDisk, RenderWithStatsWritesBothOrNeither) {
  const fs::path roomy = dir_ / "roomy";
  fs::create_directories(roomy);
  fs::copy_file(earlier("out.png"), roomy / "out.png");
  expect_clean_failure("render " + (dir_ / "in/s.json").string() + " --quiet --seed 5 -o " +
                           (roomy / "out.png").string() + " --stats DISK/stats.json",
                       "DISK/stats.json");
  EXPECT_EQ(test::read_file(roomy / "out.png"), test::read_file(earlier("out.png")));
  EXPECT_EQ(std::distance(fs::directory_iterator(roomy), fs::directory_iterator()), 1) << "a temporary was left";
}

TEST_F(FullDisk, PartialFilesAndMergeKeepTheirEarlierFiles) {
  expect_clean_failure("render " + (dir_ / "in/s.json").string() +
                           " --quiet --width 512 --height 512 --samples 0:1 -o DISK/part.partial",
                       "part.partial", {0, 8});
  expect_clean_failure("merge " + earlier("part.partial") + " " + earlier("rest.partial") + " -o DISK/out.exr",
                       "out.exr");
}

TEST_F(FullDisk, GenerateBundleCompareAndConvergeKeepTheirEarlierFiles) {
  expect_clean_failure("generate terrain --triangles 20000 -o DISK/mesh.obj", "mesh.obj", {0, 8});
  expect_clean_failure("bundle " + (dir_ / "in/s.json").string() + " -o DISK/s.bundle", "s.bundle");
  expect_clean_failure(
      "compare " + earlier("out.exr") + " " + (dir_ / "in/other.exr").string() + " --diff DISK/out.exr", "out.exr");
  expect_clean_failure("bench converge " + (dir_ / "in/s.json").string() +
                           " --spp 1,2 --ref-spp 4 --csv DISK/converge.csv --plot DISK/converge.png",
                       "DISK/converge", {0, 8});
}

TEST_F(FullDisk, GoldenUpdateWritesImagesAndManifestTogetherOrNotAtAll) {
  const test::GoldenSandbox box("full-disk");
  fs::copy(box.root, dir_ / "earlier/golden-root", fs::copy_options::recursive);
  // A changed scene: the update would rewrite ball.exr and the manifest's hash.
  std::ofstream(dir_ / "earlier/golden-root/scenes/ball.json")
      << test::sandbox_scene(R"({"type": "sphere", "center": [0, 0.5, 0], "radius": 0.4, "material": "red"})");
  expect_clean_failure("golden update --force --root DISK/golden-root", "DISK/golden-root/golden/");
}

// What a command prints must reach its reader: stdout on a full disk or closed was lost while
// the command exited 0.
TEST(FullStdout, PrintingToAFullDiskOrAClosedStdoutExitsTwo) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this machine";
  const std::string scene = test::source_path("scenes/cornell-box.json");
  for (const std::string redirect : {"> /dev/full", ">&-"})
    for (const std::string& command : {"info " + scene, "golden list --root " + std::string(TRACER_SOURCE_DIR)}) {
      std::string output;
      EXPECT_EQ(test::run_tracer(command + " " + redirect, &output), 2) << command << " " << redirect;
      EXPECT_NE(output.find("error: standard output: cannot write: "), std::string::npos) << output;
    }
}

}  // namespace
}  // namespace tracer
