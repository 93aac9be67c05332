// Checking one golden: render its scene with the manifest's options, hash the pixels and
// judge the result against the reference image. A golden passes only on identical pixels
// (or, where its entry documents why, within a metric tolerance); NaN or inf in the new
// image always fails. Checking never writes under golden/.
#pragma once
#include <optional>
#include <string>

#include "golden/golden_manifest.h"
#include "image/compare.h"
#include "image/image.h"

namespace tracer {

struct GoldenRender {
  Image image;
  uint64_t nonfinite_samples = 0;
  uint64_t overflow_samples = 0;
  std::string hash;
  RenderOptions options;  // every option as the scene and the manifest resolved them
  double seconds = 0.0;
};

// Error: the check could not run; Skipped: the device it asks for is not on this machine.
enum class GoldenStatus { Pass, Fail, Error, Skipped };

struct GoldenOutcome {
  std::string name;
  GoldenStatus status = GoldenStatus::Error;
  std::string message;                   // one line: why it failed, or "identical"
  std::optional<CompareResult> metrics;  // new against reference, when both exist
  std::optional<Image> reference;        // the golden image, when readable
  uint64_t nonfinite_values = 0;         // NaN/inf samples and pixel values of the new image
  uint64_t overflow_samples = 0;         // samples of the new image beyond the film's range
};

enum class GoldenDevice { Cpu, Cuda };

// Renders the entry's scene; InputError when the scene is missing or invalid,
// DeviceUnavailable when the device is not there.
GoldenRender render_golden(const GoldenManifest& manifest, const GoldenEntry& entry, int threads,
                           GoldenDevice device = GoldenDevice::Cpu);

// Judges a new image against the entry's reference image file.
GoldenOutcome judge_golden(const GoldenManifest& manifest, const GoldenEntry& entry, const GoldenRender& render);

// The outcome when render_golden failed (missing scene, bad input, no device).
GoldenOutcome golden_error(const GoldenEntry& entry, const std::string& message,
                           GoldenStatus status = GoldenStatus::Error);

}  // namespace tracer
