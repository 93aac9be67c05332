// The golden checker itself, so that it cannot pass by accident: exact mode catches one
// ulp in one pixel, a moved sphere fails, every broken input fails with a clear message,
// NaN always fails, identical images pass, and checking never writes under golden/.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

#include "golden/golden_check.h"
#include "golden/golden_report.h"
#include "golden_sandbox.h"
#include "image/image_io.h"
#include "image/pixel_hash.h"
#include "io/json_reader.h"

namespace tracer {
namespace {

struct Checked {
  GoldenManifest manifest;
  GoldenRender render;
};

Checked render_entry(const test::GoldenSandbox& box, const std::string& name) {
  Checked c{read_manifest(box.root.string()), {}};
  c.render = render_golden(c.manifest, c.manifest.find(name), 1);
  return c;
}

GoldenOutcome judge(const Checked& c, const std::string& name) {
  return judge_golden(c.manifest, c.manifest.find(name), c.render);
}

TEST(GoldenChecker, IdenticalImagesPass) {
  const test::GoldenSandbox box("identical");
  const Checked c = render_entry(box, "ball");
  const GoldenOutcome o = judge(c, "ball");
  EXPECT_EQ(o.status, GoldenStatus::Pass) << o.message;
  ASSERT_TRUE(o.metrics);
  EXPECT_TRUE(o.metrics->bit_identical);
  std::string output;
  EXPECT_EQ(test::run_tracer(box.check_args("ball"), &output), 0) << output;
  EXPECT_NE(output.find("PASS"), std::string::npos) << output;
}

TEST(GoldenChecker, OneUlpInOnePixelFailsInExactMode) {
  const test::GoldenSandbox box("ulp");
  Checked c = render_entry(box, "ball");
  const size_t k = 3 * (7 * 24 + 11) + 1;  // pixel (11, 7), green
  c.render.image.rgb[k] = std::nextafter(c.render.image.rgb[k], std::numeric_limits<float>::infinity());
  c.render.hash = pixel_hash(c.render.image);
  const GoldenOutcome o = judge(c, "ball");
  EXPECT_EQ(o.status, GoldenStatus::Fail) << o.message;
  ASSERT_TRUE(o.metrics);
  EXPECT_EQ(o.metrics->pixels_not_identical, 1u);
  EXPECT_EQ(o.metrics->max_x, 11);
  EXPECT_EQ(o.metrics->max_y, 7);
  EXPECT_NE(o.message.find("1 of 384 pixels differ"), std::string::npos) << o.message;
}

TEST(GoldenChecker, NegativeZeroAgainstPositiveZeroFails) {
  const test::GoldenSandbox box("zero");
  Checked c = render_entry(box, "ball");
  Image black = c.render.image;
  for (float& v : black.rgb) v = 0.0f;
  write_image(black, c.manifest.image_path(c.manifest.find("ball")));
  GoldenEntry entry = c.manifest.find("ball");
  entry.hash = pixel_hash(black);
  c.render.image = black;
  c.render.image.rgb[0] = -0.0f;
  c.render.hash = pixel_hash(c.render.image);
  EXPECT_EQ(judge_golden(c.manifest, entry, c.render).status, GoldenStatus::Fail);
}

TEST(GoldenChecker, NanInTheNewImageFails) {
  const test::GoldenSandbox box("nan");
  Checked c = render_entry(box, "ball");
  c.render.image.rgb[5] = std::numeric_limits<float>::quiet_NaN();
  c.render.hash = pixel_hash(c.render.image);
  GoldenOutcome o = judge(c, "ball");
  EXPECT_EQ(o.status, GoldenStatus::Fail);
  EXPECT_NE(o.message.find("NaN"), std::string::npos) << o.message;

  // A NaN sample averaged away still fails: the renderer counted it.
  Checked d = render_entry(box, "ball");
  d.render.nonfinite_samples = 1;
  o = judge(d, "ball");
  EXPECT_EQ(o.status, GoldenStatus::Fail);
  EXPECT_NE(o.message.find("NaN"), std::string::npos) << o.message;
}

TEST(GoldenChecker, NanFailsEvenWhenTheReferenceHasTheSameNan) {
  const test::GoldenSandbox box("nan-both");
  Checked c = render_entry(box, "ball");
  c.render.image.rgb[5] = std::numeric_limits<float>::quiet_NaN();
  c.render.hash = pixel_hash(c.render.image);
  GoldenEntry entry = c.manifest.find("ball");
  write_image(c.render.image, c.manifest.image_path(entry));
  entry.hash = c.render.hash;
  EXPECT_EQ(judge_golden(c.manifest, entry, c.render).status, GoldenStatus::Fail);
}

TEST(GoldenChecker, MovedSphereFailsAndWritesTheReportImages) {
  const test::GoldenSandbox box("moved");
  box.move_ball();
  const auto report = box.root / "report";
  const auto before = box.golden_files();
  std::string output;
  EXPECT_EQ(test::run_tracer(box.check_args("ball", report.string()), &output), 1) << output;
  EXPECT_NE(output.find("FAIL"), std::string::npos) << output;
  EXPECT_NE(output.find("golden update --filter '^ball$'"), std::string::npos) << output;
  EXPECT_EQ(test::run_tracer(box.check_args("box", report.string()), &output), 0) << output;
  for (const char* f : {"new.exr", "new.png", "reference.png", "difference.png"})
    EXPECT_TRUE(std::filesystem::exists(report / "ball" / f)) << f;
  EXPECT_FALSE(std::filesystem::exists(report / "box")) << "a passing golden writes no images";
  const Json row = parse_json_text(box.read("report/rows/ball.json"), "ball.json");
  EXPECT_EQ(row["status"], "fail");
  EXPECT_GT(row["metrics"]["not_identical"].get<uint64_t>(), 0u);
  EXPECT_EQ(box.golden_files(), before) << "checking must never write under golden/";
}

TEST(GoldenChecker, AmplifiedDifferenceMapsTheLargestErrorToOne) {
  Image a{2, 1, {0.5f, 0.5f, 0.5f, 0.1f, 0.2f, 0.3f}}, b = a, d;
  b.rgb[4] += 1e-3f;
  a.rgb[0] = std::numeric_limits<float>::quiet_NaN();
  const float scale = amplified_difference(a, b, d);
  EXPECT_NEAR(scale * std::abs(a.rgb[4] - b.rgb[4]), 1.0f, 1e-6f);
  EXPECT_EQ(d.rgb[4], std::abs(a.rgb[4] - b.rgb[4]) * scale);
  EXPECT_EQ(d.rgb[0], 1.0f);  // NaN pixel drawn magenta
  EXPECT_EQ(d.rgb[1], 0.0f);
  EXPECT_EQ(d.rgb[2], 1.0f);
}

// Every broken input is an error (exit 2) whose message names what is wrong.
struct BrokenCase {
  const char* name;
  void (*breakit)(const test::GoldenSandbox&);
  const char* golden;
  const char* expected;
};

void PrintTo(const BrokenCase& c, std::ostream* os) { *os << c.name; }

class GoldenCheckerBroken : public testing::TestWithParam<BrokenCase> {};

TEST_P(GoldenCheckerBroken, FailsWithAClearMessage) {
  const test::GoldenSandbox box(GetParam().name);
  GetParam().breakit(box);
  const auto report = box.root / "report";
  std::string output;  // stderr alone: an error is not printed on stdout
  EXPECT_EQ(test::run_tracer(box.check_args(GetParam().golden, report.string()) + " 2>&1 >/dev/null", &output), 2)
      << output;
  EXPECT_NE(output.find("ERROR"), std::string::npos) << output;
  EXPECT_NE(output.find(GetParam().expected), std::string::npos)
      << "expected \"" << GetParam().expected << "\" in: " << output;
  const Json row = parse_json_text(box.read("report/rows/" + std::string(GetParam().golden) + ".json"), "row");
  EXPECT_EQ(row["status"], "error");
}

const BrokenCase kBroken[] = {
    {"missing-image", [](const test::GoldenSandbox& b) { std::filesystem::remove(b.root / "golden/ball.exr"); }, "ball",
     "ball.exr: the reference image does not exist"},
    {"corrupt-image", [](const test::GoldenSandbox& b) { b.write("golden/ball.exr", "not an image"); }, "ball",
     "corrupt reference image"},
    {"swapped-image",
     [](const test::GoldenSandbox& b) {
       std::filesystem::copy_file(b.root / "golden/box.exr", b.root / "golden/ball.exr",
                                  std::filesystem::copy_options::overwrite_existing);
     },
     "ball", "edited without `tracer golden update`"},
    {"missing-entry", [](const test::GoldenSandbox&) {}, "sphere", "no entry named \"sphere\""},
    {"malformed-manifest", [](const test::GoldenSandbox& b) { b.write("golden/manifest.json", "{\"format\": "); },
     "ball", "manifest.json:1:12: malformed JSON"},
    {"missing-manifest", [](const test::GoldenSandbox& b) { std::filesystem::remove(b.root / "golden/manifest.json"); },
     "ball", "cannot open the golden manifest"},
    {"bad-hash",
     [](const test::GoldenSandbox& b) {
       std::string m = b.read("golden/manifest.json");
       m.replace(m.find("sha1:"), 5, "md5::");
       b.write("golden/manifest.json", m);
     },
     "ball", "goldens.ball.hash: expected \"sha1:\""},
    {"unknown-key",
     [](const test::GoldenSandbox& b) {
       std::string m = b.read("golden/manifest.json");
       m.replace(m.find("\"scene\""), 7, "\"secne\": 1, \"scene\"");
       b.write("golden/manifest.json", m);
     },
     "box", "secne"},
    {"no-hash-yet",
     [](const test::GoldenSandbox& b) {
       b.write("golden/manifest.json",
               R"({"format": "tracer-golden/1", "goldens": {"ball": {"scene": "scenes/ball.json"}}})");
     },
     "ball", "new golden: the manifest has no hash yet"},
    {"scene-gone", [](const test::GoldenSandbox& b) { std::filesystem::remove(b.root / "scenes/ball.json"); }, "ball",
     "goldens.ball.scene: scene file"},
    {"tolerance-without-reason",
     [](const test::GoldenSandbox& b) {
       std::string m = b.read("golden/manifest.json");
       m.replace(m.find("\"exact\""), 7, R"({"fail": 0.01, "why": ""})");
       b.write("golden/manifest.json", m);
     },
     "ball", "a tolerance needs a reason"},
    {"name-too-long",  // a name of any length once reached std::regex's recursion in golden update --filter
     [](const test::GoldenSandbox& b) {
       std::string m = b.read("golden/manifest.json");
       m.replace(m.find("\"box\""), 5, "\"" + std::string(101, 'b') + "\"");
       b.write("golden/manifest.json", m);
     },
     "ball", "at most 100 characters"},
    {"option-beyond-a-limit",  // was reported as the scene's command-line --grid-resolution
     [](const test::GoldenSandbox& b) {
       std::string m = b.read("golden/manifest.json");
       const size_t options = m.find("\"options\": {", m.find("\"ball\""));
       m.replace(options, 12, R"("options": {"grid_resolution": 5000, )");
       b.write("golden/manifest.json", m);
     },
     "ball", "manifest.json: goldens.ball.options.grid_resolution (the options of "},
};

INSTANTIATE_TEST_SUITE_P(Inputs, GoldenCheckerBroken, testing::ValuesIn(kBroken), [](const auto& info) {
  std::string n = info.param.name;
  for (char& ch : n) ch = ch == '-' ? '_' : ch;
  return n;
});

TEST(GoldenChecker, ToleranceModePassesSmallDifferencesOnly) {
  const test::GoldenSandbox box("tolerance");
  std::string m = box.read("golden/manifest.json");
  m.replace(m.find("\"exact\""), 7, R"({"fail": 0.01, "failpercent": 0, "why": "test of the tolerance mode"})");
  box.write("golden/manifest.json", m);
  Checked c = render_entry(box, "ball");
  c.render.image.rgb[100] += 0.005f;
  c.render.hash = pixel_hash(c.render.image);
  GoldenOutcome o = judge(c, "ball");
  EXPECT_EQ(o.status, GoldenStatus::Pass) << o.message;
  EXPECT_NE(o.message.find("test of the tolerance mode"), std::string::npos) << o.message;
  c.render.image.rgb[100] += 0.02f;
  c.render.hash = pixel_hash(c.render.image);
  o = judge(c, "ball");
  EXPECT_EQ(o.status, GoldenStatus::Fail) << o.message;
}

}  // namespace
}  // namespace tracer
