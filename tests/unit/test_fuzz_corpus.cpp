// The bundle fuzz target's seeds (tests/fuzz/corpus/bundle: bundles less their checksum) are
// bundles this build reads whole, so that mutations start from inputs that reach the view's
// fields. A change of the SceneView layout makes them stale (the reader then refuses every
// seed at its first section); rewrite them as docs/fuzzing.md says.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "bundle/scene_bundle.h"
#include "io/sha1.h"
#include "test_util.h"

namespace fs = std::filesystem;

namespace tracer {
namespace {

TEST(FuzzCorpus, EveryBundleSeedReadsWithThisBuildsLayout) {
  const fs::path corpus = test::source_path("tests/fuzz/corpus/bundle");
  const fs::path dir = test::temp_dir("fuzz-corpus");
  size_t seeds = 0;
  for (const auto& entry : fs::directory_iterator(corpus)) {
    std::string bytes = test::read_file(entry.path());
    Sha1 sha;
    sha.append(bytes.data(), bytes.size());
    unsigned char digest[20];
    sha.digest(digest);
    bytes.append(reinterpret_cast<const char*>(digest), sizeof digest);
    const fs::path whole = dir / entry.path().filename();
    std::ofstream(whole, std::ios::binary) << bytes;
    EXPECT_NO_THROW(read_scene_bundle(whole.string())) << entry.path();
    ++seeds;
  }
  EXPECT_GE(seeds, 4u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tracer
