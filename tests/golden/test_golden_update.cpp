// `tracer golden update`: rewrites only goldens that are new or differ, prints what
// changed, writes nothing when any matching golden fails to render, and refuses to run
// over uncommitted edits under golden/ unless --force.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "golden/golden_manifest.h"
#include "golden_sandbox.h"
#include "io/json_reader.h"

namespace tracer {
namespace {

// The sandbox as a git checkout with everything committed.
void commit_all(const test::GoldenSandbox& box) {
  const std::string git = "git -C " + box.root.string() + " -c user.name=test -c user.email=test@example.com ";
  ASSERT_EQ(std::system((git + "init -q && " + git + "add -A && " + git + "commit -qm goldens").c_str()), 0);
}

std::string update_args(const test::GoldenSandbox& box, const std::string& extra = "") {
  return "golden update --root " + box.root.string() + " " + extra;
}

TEST(GoldenUpdate, RefusesUncommittedEditsUnderGoldenUnlessForced) {
  const test::GoldenSandbox box("refuse");
  commit_all(box);
  box.write("golden/notes.txt", "an untracked file");
  box.move_ball();
  const auto before = box.golden_files();
  std::string output;
  EXPECT_EQ(test::run_tracer(update_args(box), &output), 2) << output;
  EXPECT_NE(output.find("has uncommitted edits"), std::string::npos) << output;
  EXPECT_NE(output.find("golden/notes.txt"), std::string::npos) << "the refusal lists the edits: " << output;
  EXPECT_EQ(box.golden_files(), before);
  EXPECT_EQ(test::run_tracer(update_args(box, "--force"), &output), 0) << output;
  EXPECT_NE(box.golden_files(), before);
}

TEST(GoldenUpdate, RefusesOutsideAGitCheckoutUnlessForced) {
  const test::GoldenSandbox box("no-git");
  std::string output;
  EXPECT_EQ(test::run_tracer(update_args(box), &output), 2) << output;
  EXPECT_NE(output.find("cannot tell whether golden/ has uncommitted edits"), std::string::npos) << output;
  EXPECT_EQ(test::run_tracer(update_args(box, "--force"), &output), 0) << output;
}

TEST(GoldenUpdate, RewritesOnlyTheGoldenThatChangedAndPrintsIt) {
  const test::GoldenSandbox box("changed");
  commit_all(box);
  const auto before = box.golden_files();
  box.move_ball();
  std::string output;
  EXPECT_EQ(test::run_tracer(box.check_args("ball"), &output), 1) << output;
  EXPECT_EQ(test::run_tracer(update_args(box), &output), 0) << output;
  EXPECT_NE(output.find("ball"), std::string::npos) << output;
  EXPECT_NE(output.find("changed"), std::string::npos) << output;
  EXPECT_EQ(output.find("box "), std::string::npos) << "unchanged goldens are not listed: " << output;
  EXPECT_NE(output.find("1 of 2 matching goldens rewritten, 1 unchanged"), std::string::npos) << output;
  const auto after = box.golden_files();
  EXPECT_EQ(after.at("box.exr"), before.at("box.exr"));
  EXPECT_NE(after.at("ball.exr"), before.at("ball.exr"));
  EXPECT_NE(after.at("manifest.json"), before.at("manifest.json"));
  EXPECT_EQ(test::run_tracer(box.check_args("ball"), &output), 0) << output;
  EXPECT_EQ(test::run_tracer(box.check_args("box"), &output), 0) << output;
  // A second update finds nothing to do and leaves every byte alone.
  EXPECT_EQ(test::run_tracer(update_args(box, "--force"), &output), 0) << output;
  EXPECT_NE(output.find("0 of 2 matching goldens rewritten"), std::string::npos) << output;
  EXPECT_EQ(box.golden_files(), after);
}

TEST(GoldenUpdate, FilterSelectsGoldensByName) {
  const test::GoldenSandbox box("filter");
  commit_all(box);
  box.move_ball();
  const auto before = box.golden_files();
  std::string output;
  EXPECT_EQ(test::run_tracer(update_args(box, "--filter '^box$'"), &output), 0) << output;
  EXPECT_NE(output.find("0 of 1 matching goldens rewritten"), std::string::npos) << output;
  EXPECT_EQ(box.golden_files(), before);
  EXPECT_EQ(test::run_tracer(update_args(box, "--filter '^sphere'"), &output), 2) << output;
  EXPECT_NE(output.find("no golden name matches --filter"), std::string::npos) << output;
  EXPECT_EQ(test::run_tracer(update_args(box, "--filter '(('"), &output), 2) << output;
  EXPECT_NE(output.find("not a valid regular expression"), std::string::npos) << output;
  // Deeply nested groups ended in SIGSEGV inside std::regex: a bounded pattern is refused first.
  const std::string nested = std::string(20000, '(') + "a" + std::string(20000, ')');
  EXPECT_EQ(test::run_tracer(update_args(box, "--filter '" + nested + "'"), &output), 2) << output.substr(0, 300);
  EXPECT_NE(output.find("--filter: 40001 characters; at most 256"), std::string::npos) << output.substr(0, 300);
  EXPECT_EQ(box.golden_files(), before);
}

TEST(GoldenUpdate, OneBadSceneLeavesGoldenUntouched) {
  const test::GoldenSandbox box("bad-scene");
  commit_all(box);
  box.move_ball();
  box.write("scenes/box.json", "{\"format\": \"tracer-scene/1\",");
  const auto before = box.golden_files();
  std::string output;
  EXPECT_EQ(test::run_tracer(update_args(box), &output), 2) << output;
  EXPECT_NE(output.find("box.json"), std::string::npos) << output;
  EXPECT_EQ(box.golden_files(), before);
}

TEST(GoldenUpdate, NewEntryGetsItsImageHashAndEveryOption) {
  const test::GoldenSandbox box("new");
  std::string m = box.read("golden/manifest.json");
  m.insert(m.find("\"box\""),
           R"("ball-grid": {"scene": "scenes/ball.json", "options": {"sampler": "grid", "spp": 4}}, )");
  box.write("golden/manifest.json", m);
  std::string output;
  EXPECT_EQ(test::run_tracer(update_args(box, "--force --filter grid"), &output), 0) << output;
  EXPECT_NE(output.find("ball-grid"), std::string::npos) << output;
  EXPECT_NE(output.find("new"), std::string::npos) << output;
  const GoldenEntry e = read_manifest(box.root.string()).find("ball-grid");
  EXPECT_TRUE(e.options.complete());
  EXPECT_EQ(*e.options.sampler, SamplerKind::Grid);
  EXPECT_EQ(*e.options.spp, 4u);
  EXPECT_EQ(*e.options.width, 24u);
  EXPECT_EQ(*e.options.integrator, IntegratorKind::Whitted);
  EXPECT_EQ(e.hash.size(), 45u);
  EXPECT_TRUE(std::filesystem::exists(box.root / "golden/ball-grid.exr"));
  EXPECT_EQ(test::run_tracer(box.check_args("ball-grid"), &output), 0) << output;
}

TEST(GoldenUpdate, MissingImageWithAnUnchangedRenderIsRepaired) {
  const test::GoldenSandbox box("repair");
  std::filesystem::remove(box.root / "golden/box.exr");
  std::string output;
  EXPECT_EQ(test::run_tracer(update_args(box, "--force"), &output), 0) << output;
  EXPECT_NE(output.find("repaired"), std::string::npos) << output;
  EXPECT_EQ(test::run_tracer(box.check_args("box"), &output), 0) << output;
}

// The manifest is written by appending each entry in name order (writing it by key lookup took
// time quadratic in its size): a large manifest keeps every entry, in order, as it was.
TEST(GoldenUpdate, UpdatingOneOfManyGoldensKeepsEveryOtherEntryInOrder) {
  const test::GoldenSandbox box("many");
  std::string m = box.read("golden/manifest.json");
  std::string extra;
  for (int i = 0; i < 5000; ++i)
    extra += "\"many-" + std::to_string(i) + "\": {\"scene\": \"scenes/ball.json\"}, ";
  m.insert(m.find("\"ball\""), extra);
  box.write("golden/manifest.json", m);
  const std::vector<GoldenEntry> before = read_manifest(box.root.string()).entries;
  std::string output;
  box.write("scenes/ball.json", test::sandbox_scene(test::kSandboxBox));
  EXPECT_EQ(test::run_tracer(update_args(box, "--force --filter '^ball$'"), &output), 0) << output;
  const std::vector<GoldenEntry> after = read_manifest(box.root.string()).entries;
  ASSERT_EQ(after.size(), before.size());
  for (size_t i = 0; i < after.size(); ++i) {
    EXPECT_EQ(after[i].name, before[i].name);
    EXPECT_EQ(after[i].hash == before[i].hash, after[i].name != "ball") << after[i].name;
  }
}

}  // namespace
}  // namespace tracer
