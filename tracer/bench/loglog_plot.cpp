#include "bench/loglog_plot.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "io/input_error.h"

namespace tracer {
namespace {

constexpr const char* kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr int kWidth = 800, kHeight = 560, kLeft = 90, kRight = 30, kTop = 50, kBottom = 70;
const float kColours[][3] = {
    {0.12f, 0.47f, 0.71f}, {0.84f, 0.15f, 0.16f}, {0.17f, 0.63f, 0.17f}, {0.58f, 0.40f, 0.74f}};

struct Axis {
  double lo, hi;  // decades, log10
  static Axis around(double min_value, double max_value) {
    Axis a{std::floor(std::log10(min_value)), std::ceil(std::log10(max_value))};
    if (a.hi <= a.lo) a.hi = a.lo + 1;
    return a;
  }
  double fraction(double v) const { return (std::log10(v) - lo) / (hi - lo); }
};

std::string decade_label(double exponent) {
  const int e = static_cast<int>(exponent);
  return e == 0 ? "1" : e == 1 ? "10" : "1e" + std::to_string(e);
}

}  // namespace

void add_loglog_plot(OutputBatch& batch, const std::string& path, const PlotLabels& labels,
                     const std::vector<PlotSeries>& series) {
  namespace IBA = OIIO::ImageBufAlgo;
  if (!std::filesystem::exists(kFont))
    throw InputError(std::string(kFont) + ": font not found (install fonts-dejavu-core)");
  double xmin = INFINITY, xmax = 0, ymin = INFINITY, ymax = 0;
  for (const PlotSeries& s : series)
    for (size_t i = 0; i < s.x.size(); ++i)
      if (s.x[i] > 0 && s.y[i] > 0)
        xmin = std::min(xmin, s.x[i]), xmax = std::max(xmax, s.x[i]), ymin = std::min(ymin, s.y[i]),
        ymax = std::max(ymax, s.y[i]);
  if (!(xmax > 0)) throw InputError(path + ": nothing positive to plot");
  const Axis ax = Axis::around(xmin, xmax), ay = Axis::around(ymin, ymax);
  const int plot_w = kWidth - kLeft - kRight, plot_h = kHeight - kTop - kBottom;
  const auto px = [&](double x) { return kLeft + static_cast<int>(std::lround(ax.fraction(x) * plot_w)); };
  const auto py = [&](double y) { return kTop + plot_h - static_cast<int>(std::lround(ay.fraction(y) * plot_h)); };

  OIIO::ImageBuf img(OIIO::ImageSpec(kWidth, kHeight, 3, OIIO::TypeDesc::UINT8));
  const float white[] = {1, 1, 1}, grid[] = {0.88f, 0.88f, 0.88f}, ink[] = {0.1f, 0.1f, 0.1f};
  IBA::fill(img, white);
  for (double e = ax.lo; e <= ax.hi; ++e) {
    const int x = px(std::pow(10.0, e));
    IBA::render_line(img, x, kTop, x, kTop + plot_h, grid);
    IBA::render_text(img, x - 12, kTop + plot_h + 22, decade_label(e), 14, kFont, ink);
  }
  for (double e = ay.lo; e <= ay.hi; ++e) {
    const int y = py(std::pow(10.0, e));
    IBA::render_line(img, kLeft, y, kLeft + plot_w, y, grid);
    IBA::render_text(img, kLeft - 50, y + 5, decade_label(e), 14, kFont, ink);
  }
  IBA::render_box(img, kLeft, kTop, kLeft + plot_w, kTop + plot_h, ink);
  IBA::render_text(img, kLeft, 30, labels.title, 18, kFont, ink);
  IBA::render_text(img, kLeft + plot_w / 2 - 60, kHeight - 20, labels.x, 15, kFont, ink);
  IBA::render_text(img, 8, kTop - 12, labels.y, 15, kFont, ink);
  for (size_t k = 0; k < series.size(); ++k) {
    const OIIO::cspan<float> c(kColours[k % 4], 3);
    const PlotSeries& s = series[k];
    for (size_t i = 0; i < s.x.size(); ++i) {
      if (!(s.x[i] > 0 && s.y[i] > 0)) continue;
      const int x = px(s.x[i]), y = py(s.y[i]);
      IBA::render_box(img, x - 3, y - 3, x + 3, y + 3, c, true);
      if (i > 0 && s.x[i - 1] > 0 && s.y[i - 1] > 0) IBA::render_line(img, px(s.x[i - 1]), py(s.y[i - 1]), x, y, c);
    }
    const int ly = kTop + 20 + 22 * static_cast<int>(k);
    IBA::render_box(img, kLeft + plot_w - 200, ly - 8, kLeft + plot_w - 188, ly + 4, c, true);
    IBA::render_text(img, kLeft + plot_w - 180, ly + 4, s.label, 14, kFont, ink);
  }
  OIIO::Filesystem::IOVecOutput memory;  // encoded in memory, written by the batch (see image_io.cpp)
  img.set_write_ioproxy(&memory);
  if (!img.write(path, OIIO::TypeDesc::UINT8, "png"))
    throw InputError(path + ": cannot encode the plot: " + img.geterror());
  batch.add(path, std::string(memory.buffer().begin(), memory.buffer().end()));
}

}  // namespace tracer
