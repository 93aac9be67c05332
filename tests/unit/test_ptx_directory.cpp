// Where `tracer audit cuda` keeps its PTX (tracer/audit/ptx_directory.h): nvcc writes into a new
// directory, which replaces --ptx-dir at the end; a link, a FIFO or a user's directory given as
// --ptx-dir is refused before any work and left exactly as it was.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "audit/cuda_audit.h"
#include "audit/ptx_directory.h"
#include "io/input_error.h"
#include "test_util.h"

namespace fs = std::filesystem;

namespace tracer {
namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void spill(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

TEST(PtxDirectory, ALinkAFifoOrAUsersDirectoryIsRefusedAndLeftAsItWas) {
  const fs::path dir = test::temp_dir("ptx-directory-refused");
  spill(dir / "precious.txt", "the user's");
  fs::create_symlink(dir / "precious.txt", dir / "link");
  ASSERT_EQ(mkfifo((dir / "fifo").c_str(), 0600), 0);
  fs::create_directories(dir / "mine");
  spill(dir / "mine" / "notes.txt", "kept");
  for (const char* name : {"link", "fifo", "mine", "precious.txt"}) {
    EXPECT_THROW(PtxDirectory((dir / name).string(), false), InputError) << name;
  }
  EXPECT_EQ(slurp(dir / "precious.txt"), "the user's");
  EXPECT_EQ(slurp(dir / "mine" / "notes.txt"), "kept");
  EXPECT_TRUE(fs::is_symlink(dir / "link"));
  // nothing is left behind: the staging directories were never made
  size_t entries = 0;
  for (const auto& e : fs::directory_iterator(dir))
    entries += e.path().filename().string().find(".partial-") != std::string::npos;
  EXPECT_EQ(entries, 0u);
  fs::remove_all(dir);
}

TEST(PtxDirectory, TheNewDirectoryReplacesAnEarlierAuditsAndNeverWritesThroughItsLinks) {
  const fs::path dir = test::temp_dir("ptx-directory-replace");
  spill(dir / "precious.txt", "the user's");
  const std::string ptx = (dir / "ptx").string();
  {
    PtxDirectory first(ptx + "/", false);  // a trailing slash names the same directory
    EXPECT_EQ(first.path(), ptx);
    spill(fs::path(first.staging()) / "old.ptx", "old");
    first.keep();
  }
  ASSERT_TRUE(fs::exists(fs::path(ptx) / kPtxDirectoryMarker));
  fs::create_symlink(dir / "precious.txt", fs::path(ptx) / "planted.ptx");  // planted in the kept directory
  {
    PtxDirectory second(ptx, false);
    EXPECT_NE(second.staging(), ptx);
    spill(fs::path(second.staging()) / "planted.ptx", "new PTX");  // nvcc's write lands in the new directory
    second.keep();
  }
  EXPECT_EQ(slurp(dir / "precious.txt"), "the user's");
  EXPECT_EQ(slurp(fs::path(ptx) / "planted.ptx"), "new PTX");
  EXPECT_FALSE(fs::exists(fs::path(ptx) / "old.ptx"));
  {
    PtxDirectory abandoned(ptx, false);  // not kept: its staging directory goes, the kept one stays
    spill(fs::path(abandoned.staging()) / "partial.ptx", "partial");
  }
  EXPECT_EQ(slurp(fs::path(ptx) / "planted.ptx"), "new PTX");
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find("ptx.partial-"), std::string::npos) << e.path();
  fs::remove_all(dir);
}

TEST(PtxDirectory, TwoSourcesNeverShareAPtxFile) {
  EXPECT_NE(ptx_path_for("d", "cuda/a_b.cu", "90"), ptx_path_for("d", "cuda_a/b.cu", "90"));
  EXPECT_NE(ptx_path_for("d", "cuda/a/b.cu", "90"), ptx_path_for("d", "cuda/a_b.cu", "90"));
  EXPECT_EQ(ptx_path_for("d", "cuda/gpu_film.cu", "90"), "d/cuda/gpu_film.cu.compute_90.ptx");
}

// nvcc failing is no verdict on the instructions (before, exit 1 "FAIL", and the incomplete PTX
// replaced the earlier audit's): exit 2, and the earlier directory as it was.
TEST(PtxDirectory, AnNvccFailureExitsTwoAndKeepsTheEarlierAuditsPtx) {
  const fs::path dir = test::temp_dir("ptx-directory-nvcc-fails");
  fs::create_directories(dir / "tree/cuda");
  spill(dir / "tree/cuda/broken.cu", "#error this source does not compile\n");
  fs::create_directories(dir / "ptx");
  spill(dir / "ptx" / kPtxDirectoryMarker, "an earlier audit\n");
  spill(dir / "ptx/earlier.ptx", "earlier PTX");
  std::string output;
  const int status = test::run_tracer("audit cuda --root " + (dir / "tree").string() + " --ptx-dir " +
                                          (dir / "ptx").string(),
                                      &output);
  if (status == 77) GTEST_SKIP() << output;
  EXPECT_EQ(status, 2) << output;
  EXPECT_NE(output.find("nvcc failed on 2 of 2 modules (the first: cuda/broken.cu"), std::string::npos) << output;
  EXPECT_NE(output.find("this source does not compile"), std::string::npos) << output;
  EXPECT_EQ(slurp(dir / "ptx/earlier.ptx"), "earlier PTX");
  size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 2u) << "a staging directory was left beside " << dir / "ptx";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tracer
