// The golden report in the build tree (docs/golden.md). Each check writes one row,
// REPORT/rows/NAME.json, and for a failure the images REPORT/NAME/{new.exr, new.png,
// reference.png, difference.png}; `tracer golden report` assembles every row into
// REPORT/index.html: failing rows first, each with new | reference | difference, the
// metrics and the exact command that would update that golden.
#pragma once
#include <string>

#include "golden/golden_check.h"

namespace tracer {

struct ReportCounts {
  int passed = 0, failed = 0, errors = 0, skipped = 0;
};

// Writes the row (and, unless the golden passed, its images). `render` is null when the
// golden could not be rendered.
// Before a check renders: makes REPORT_DIR a marked report directory when nothing is there,
// or InputError naming it and --report when it cannot hold rows.
void prepare_report_dir(const std::string& report_dir);

void write_report_row(const std::string& report_dir, const GoldenManifest& manifest, const GoldenEntry& entry,
                      const GoldenRender* render, const GoldenOutcome& outcome);

// Removes every row and image, so a run's report shows only that run's goldens: only from a
// directory this tracer made (it holds the marker file); a missing or empty one is made one.
// InputError, touching nothing, for any other directory, a symbolic link or a file.
void reset_report(const std::string& report_dir);

// Writes REPORT/index.html from the rows present and returns their counts.
ReportCounts assemble_report(const std::string& report_dir);

// |new - reference| scaled so the largest difference is 1; NaN/inf pixels of the new
// image are magenta. Returns the scale used (0 when the images are identical).
float amplified_difference(const Image& fresh, const Image& reference, Image& out);

// The shell command that regenerates one golden, run from anywhere.
std::string update_command(const GoldenManifest& manifest, const std::string& name);

}  // namespace tracer
