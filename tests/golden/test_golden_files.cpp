// What golden/ may hold: the manifest and one image per entry, nothing orphaned, within
// the 20 MB budget (docs/golden.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "golden/golden_manifest.h"
#include "test_util.h"

namespace tracer {
namespace {

TEST(GoldenFiles, EveryFileBelongsToTheManifest) {
  const GoldenManifest manifest = read_manifest(TRACER_SOURCE_DIR);
  std::set<std::string> expected = {"manifest.json"};
  for (const GoldenEntry& e : manifest.entries) expected.insert(e.name + ".exr");
  std::set<std::string> present;
  for (const auto& f : std::filesystem::directory_iterator(std::filesystem::path(TRACER_SOURCE_DIR) / "golden"))
    present.insert(f.path().filename().string());
  for (const std::string& f : present) EXPECT_TRUE(expected.count(f)) << "golden/" << f << " is not in the manifest";
  for (const std::string& f : expected) EXPECT_TRUE(present.count(f)) << "golden/" << f << " is missing";
}

TEST(GoldenFiles, DirectoryStaysUnderTwentyMegabytes) {
  uintmax_t bytes = 0;
  for (const auto& f : std::filesystem::directory_iterator(std::filesystem::path(TRACER_SOURCE_DIR) / "golden"))
    bytes += f.file_size();
  EXPECT_LT(bytes, 20u * 1024 * 1024) << "golden/ holds " << bytes << " bytes";
}

}  // namespace
}  // namespace tracer
