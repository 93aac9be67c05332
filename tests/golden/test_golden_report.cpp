// The HTML report opens as a page in a real browser: headless Chromium (Debian's
// `chromium`, installed by ci/install-deps.sh) loads a report with one failing and one
// passing golden, every image in it loads, the failing row comes first with its update
// command and a flip view at a whole-pixel zoom that shows the reference when asked, and a screenshot of the page is a
// picture rather than a blank canvas.
#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include "golden_sandbox.h"
#include "image/image_io.h"

namespace tracer {
namespace {

std::string chromium(const std::filesystem::path& profile) {
  return "timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --user-data-dir=" +
         profile.string() + " --virtual-time-budget=10000 ";
}

// One failing check with --report leaves a page that exists and shows it, as it says.
TEST(GoldenReport, ACheckAloneLeavesTheReportItNames) {
  const test::GoldenSandbox box("report-one");
  box.move_ball();
  const auto report = box.root / "report";
  std::string output;
  ASSERT_EQ(test::run_tracer(box.check_args("ball", report.string()), &output), 1) << output;
  const std::string index = (std::filesystem::absolute(report) / "index.html").string();
  EXPECT_NE(output.find("report: " + index), std::string::npos) << output;
  ASSERT_TRUE(std::filesystem::exists(index)) << output;
  const std::string page = test::read_file(index);
  EXPECT_NE(page.find("<tr class=\"fail\" id=\"ball\">"), std::string::npos) << page;
  EXPECT_NE(page.find("1 differ"), std::string::npos) << page;
}

// A row missing a key (edited, cut short) is refused naming the file and the key; it printed the
// JSON library's bare exception.
TEST(GoldenReport, ARowMissingAKeyIsRefusedNamingTheFile) {
  const test::GoldenSandbox box("report-bad-row");
  box.move_ball();
  const auto report = box.root / "report";
  std::string output;
  ASSERT_EQ(test::run_tracer(box.check_args("ball", report.string()), &output), 1) << output;
  std::string row = test::read_file(report / "rows" / "ball.json");
  row.replace(row.find("\"scene\""), 7, "\"scenery\"");
  std::ofstream(report / "rows" / "ball.json") << row;
  EXPECT_EQ(test::run_tracer("golden report --report " + report.string(), &output), 2) << output;
  EXPECT_NE(output.find("ball.json: not a report row as golden check writes it: key 'scene' not found"),
            std::string::npos)
      << output;
}

TEST(GoldenReport, OpensInHeadlessChromiumWithEveryImage) {
  if (test::run_command("command -v chromium") != 0)
    GTEST_SKIP() << "chromium is not installed; ci/install-deps.sh installs it";
  const test::GoldenSandbox box("report");
  box.move_ball();
  const auto report = box.root / "report";
  std::string output;
  ASSERT_EQ(test::run_tracer(box.check_args("box", report.string()), &output), 0) << output;
  ASSERT_EQ(test::run_tracer(box.check_args("ball", report.string()), &output), 1) << output;
  ASSERT_EQ(test::run_tracer("golden report --report " + report.string(), &output), 0) << output;
  EXPECT_NE(output.find("1 differ, 0 could not be checked, 0 skipped, 1 identical"), std::string::npos) << output;
  const std::string page = "file://" + (report / "index.html").string();

  std::string dom;
  ASSERT_EQ(test::run_command(chromium(box.root / "profile-dom") + "--dump-dom " + page + " 2>/dev/null", &dom), 0)
      << dom;
  EXPECT_NE(dom.find("data-broken-images=\"0\""), std::string::npos)
      << "images failed to load, or the page script did not run:\n"
      << dom;
  const size_t ball = dom.find("<tr class=\"fail\" id=\"ball\">"), box_row = dom.find("<tr class=\"pass\" id=\"box\">");
  ASSERT_NE(ball, std::string::npos) << dom;
  ASSERT_NE(box_row, std::string::npos) << dom;
  EXPECT_LT(ball, box_row) << "failing rows come first";
  const std::string ball_html = dom.substr(ball, box_row - ball);
  for (const char* img : {"ball/new.png", "ball/reference.png", "ball/difference.png"})
    EXPECT_NE(ball_html.find(std::string("<img src=\"") + img), std::string::npos) << img;
  EXPECT_NE(ball_html.find("golden update --filter '^ball$'"), std::string::npos) << ball_html;
  EXPECT_NE(ball_html.find("PSNR"), std::string::npos);

  // The flip view: the new image at a whole-pixel zoom (24 pixels wide: x21, 504 px), the
  // reference once shown (here through the page's #show=reference, which pins it as a click does).
  const size_t flip = ball_html.find("<img class=\"flip\"");
  ASSERT_NE(flip, std::string::npos) << ball_html;
  const std::string flip_html = ball_html.substr(flip, ball_html.find('>', flip) - flip);
  for (const char* attribute : {"src=\"ball/new.png\"", "data-showing=\"new\"", "data-zoom=\"21\"", "width: 504px"})
    EXPECT_NE(flip_html.find(attribute), std::string::npos) << attribute << " missing: " << flip_html;
  std::string flipped;
  ASSERT_EQ(test::run_command(
                chromium(box.root / "profile-flip") + "--dump-dom '" + page + "#show=reference' 2>/dev/null", &flipped),
            0)
      << flipped;
  const size_t flipped_at = flipped.find("<img class=\"flip\"");
  ASSERT_NE(flipped_at, std::string::npos) << flipped;
  const std::string flipped_html = flipped.substr(flipped_at, flipped.find('>', flipped_at) - flipped_at);
  for (const char* attribute : {"src=\"ball/reference.png\"", "data-showing=\"reference\"", "width: 504px"})
    EXPECT_NE(flipped_html.find(attribute), std::string::npos) << attribute << " missing: " << flipped_html;

  // A laptop's 1,200 px: the failing row wraps its images instead of widening the page (the
  // flip view, three images and the metrics once needed about 1,600 px).
  std::string narrow;
  ASSERT_EQ(test::run_command(chromium(box.root / "profile-narrow") + "--window-size=1200,900 --dump-dom " + page +
                                  " 2>/dev/null",
                              &narrow),
            0)
      << narrow;
  const size_t width_at = narrow.find("data-page-width=\"");
  ASSERT_NE(width_at, std::string::npos) << narrow;
  EXPECT_LE(std::stoi(narrow.substr(width_at + 17)), 1200) << "the report scrolls sideways at 1,200 px";

  const auto shot = box.root / "screenshot.png";
  ASSERT_EQ(test::run_command(chromium(box.root / "profile-shot") +
                                  "--window-size=1000,700 --screenshot=" + shot.string() + " " + page + " 2>/dev/null",
                              &output),
            0)
      << output;
  const Image image = read_image(shot.string());
  EXPECT_EQ(image.width, 1000u);
  EXPECT_EQ(image.height, 700u);
  std::set<uint32_t> colours;
  for (size_t i = 0; i < image.rgb.size(); i += 3)
    colours.insert(static_cast<uint32_t>(image.rgb[i] * 255) << 16 |
                   static_cast<uint32_t>(image.rgb[i + 1] * 255) << 8 | static_cast<uint32_t>(image.rgb[i + 2] * 255));
  EXPECT_GT(colours.size(), 50u) << "the screenshot looks blank";
}

}  // namespace
}  // namespace tracer
