// `golden update` writes several files that must agree: each golden image and the hash the
// manifest records for it. It commits them through a journal while holding golden/ locked
// (golden/golden_lock.h, io/output_batch.h). Killed or interrupted at any rename, the next
// golden command finds every image hashing to its manifest entry and no temporary left;
// two updates at once serialize and both land. strace's fault injection stops the real
// binary at its Nth rename (the journal, the images, the manifest) with a signal.
#include <gtest/gtest.h>

#include "golden/golden_manifest.h"
#include "golden_sandbox.h"
#include "image/image_io.h"
#include "image/pixel_hash.h"

namespace tracer {
namespace {

namespace fs = std::filesystem;

// Every golden image hashes to its manifest entry, and golden/ holds no journal or temporary.
void expect_consistent(const fs::path& root, const std::string& context) {
  const GoldenManifest manifest = read_manifest(root.string());
  for (const GoldenEntry& e : manifest.entries)
    EXPECT_EQ(pixel_hash(read_image(manifest.image_path(e))), e.hash) << context << ": " << e.name;
  for (const auto& entry : fs::directory_iterator(root / "golden"))
    EXPECT_NE(entry.path().filename().string().rfind(".tracer-", 0), 0u) << context << ": " << entry.path();
}

std::string hash_of(const test::GoldenSandbox& box, const std::string& name) {
  return read_manifest(box.root.string()).find(name).hash;
}

void change_both_scenes(const test::GoldenSandbox& box) {
  box.move_ball();
  box.write("scenes/box.json", test::sandbox_scene(R"({"type": "box", "min": [-0.4, 0, -0.5], "max": [0.5, 1, 0.5],
      "material": "red"})"));
}

void replace_once(std::string& text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}

bool strace_works() { return test::run_command("strace -f -qq -o /dev/null true") == 0; }

TEST(GoldenCommit, AnUpdateStoppedAtAnyRenameLeavesImagesAndManifestAgreeing) {
  if (!strace_works()) {
    GTEST_SKIP() << "strace cannot trace here (no strace, or ptrace refused)";
  }
  // Two images and the manifest: three renames, four with the journal.
  for (const char* signal : {"KILL", "TERM", "INT"}) {
    for (int n = 1; n <= 4; ++n) {
      const test::GoldenSandbox box("commit");
      const std::string old_ball = hash_of(box, "ball");
      change_both_scenes(box);
      std::string output;
      test::run_command("strace -f -qq -o /dev/null -e trace=rename,renameat,renameat2 -e inject=rename,renameat," +
                            std::string("renameat2:signal=") + signal + ":when=" + std::to_string(n) + " " +
                            TRACER_BINARY + " golden update --force --root " + box.root.string(),
                        &output);
      const std::string context = std::string("SIG") + signal + " at rename " + std::to_string(n);
      // The next golden command finishes what a killed update committed, or removes what it had not.
      ASSERT_EQ(test::run_tracer("golden list --root " + box.root.string(), &output), 0) << context << "\n" << output;
      expect_consistent(box.root, context);
      // SIGTERM and SIGINT wait for the last rename: the update lands whole.
      if (std::string(signal) != "KILL") {
        EXPECT_NE(hash_of(box, "ball"), old_ball) << context;
      }
    }
  }
}

TEST(GoldenCommit, TwoUpdatesAtOnceSerializeAndNeitherLosesItsGolden) {
  const test::GoldenSandbox box("concurrent");
  // Two new goldens whose scenes take a moment to render, so that both updates read the
  // manifest before either writes.
  for (const char* name : {"ball", "box"}) {
    std::string text = box.read(std::string("scenes/") + name + ".json");
    replace_once(text, R"("width": 24, "height": 16)", R"("width": 96, "height": 64)");
    replace_once(text, R"("integrator": "whitted", "spp": 1, "sampler": "center")",
                 R"("integrator": "path", "spp": 64, "sampler": "stochastic")");
    box.write(std::string("scenes/") + name + ".json", text);
  }
  box.write("golden/manifest.json", R"({"format": "tracer-golden/1", "goldens": {
      "ball": {"scene": "scenes/ball.json"}, "box": {"scene": "scenes/box.json"}}})");
  const std::string update =
      std::string(TRACER_BINARY) + " golden update --force --threads 1 --root " + box.root.string() + " --filter ";
  std::string output;
  EXPECT_EQ(test::run_command(update + "'^ball$' & " + update + "'^box$' & wait %1 && wait %2", &output), 0) << output;
  EXPECT_NE(hash_of(box, "ball"), "") << output;
  EXPECT_NE(hash_of(box, "box"), "") << output;
  expect_consistent(box.root, "two updates at once");
}

}  // namespace
}  // namespace tracer
