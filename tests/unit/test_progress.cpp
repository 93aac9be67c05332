// The render's progress bar (tracer/render/progress.h): each update's own total, a fraction held
// to [0, 1]; and through a terminal (script(1) gives the render a pseudo-terminal), every
// schedule's bar ends at 100 % with no ETA below zero. Under --schedule stream the bar once
// counted samples against tiles and climbed to 409600 %.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "render/progress.h"
#include "test_util.h"

namespace tracer {
namespace {

TEST(Progress, TheLineHoldsTheFractionToOne) {
  EXPECT_NE(progress_line(0, 10, 1.0).find("  0.0%"), std::string::npos);
  EXPECT_NE(progress_line(5, 10, 1.0).find(" 50.0%  1.0s elapsed, ETA 1.0s"), std::string::npos);
  EXPECT_NE(progress_line(40960, 10, 1.0).find("100.0%  1.0s elapsed, ETA 0.0s"), std::string::npos);
  EXPECT_NE(progress_line(0, 0, 0.0).find("100.0%"), std::string::npos);
}

TEST(Progress, EverySchedulesBarEndsAtOneHundredPercentOnATerminal) {
  const std::filesystem::path dir = test::temp_dir("progress");
  for (const char* schedule : {"megakernel", "stream"}) {
    const std::string out_image = (dir / (std::string(schedule) + ".png")).string();
    std::string out;
    const std::string render = std::string(TRACER_BINARY) + " render " + test::source_path("scenes/cornell-box.json") +
                               " --width 64 --height 48 --schedule " + schedule + " -o " + out_image;
    ASSERT_EQ(test::run_command("script -qec '" + render + "' /dev/null", &out), 0) << out;
    const std::regex percent(R"(([0-9]+\.[0-9])%  [0-9.]+s elapsed, ETA (-?[0-9.]+)s)");
    int bars = 0;
    double last = -1.0;
    for (auto it = std::sregex_iterator(out.begin(), out.end(), percent); it != std::sregex_iterator(); ++it) {
      ++bars;
      last = std::stod((*it)[1]);
      EXPECT_LE(last, 100.0) << schedule << ": " << it->str();
      EXPECT_GE(std::stod((*it)[2]), 0.0) << schedule << ": " << it->str();
    }
    EXPECT_GT(bars, 0) << schedule << ": no progress bar on a terminal:\n" << out;
    EXPECT_EQ(last, 100.0) << schedule;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tracer
