// A log-log line plot drawn with OpenImageIO's drawing functions (render_line, render_box,
// render_text with DejaVu Sans from Debian's fonts-dejavu-core), written as a PNG.
#pragma once
#include <string>
#include <vector>

#include "io/output_batch.h"

namespace tracer {

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;  // positive values; points are joined in order
};

struct PlotLabels {
  std::string title, x, y;
};

// Adds the PNG to `batch` (written on its commit); InputError when it cannot be written or the
// font is missing.
void add_loglog_plot(OutputBatch& batch, const std::string& path, const PlotLabels& labels,
                     const std::vector<PlotSeries>& series);

}  // namespace tracer
