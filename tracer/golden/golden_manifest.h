// golden/manifest.json: the list of golden images (docs/golden.md). Each entry names a
// scene file (relative to the source root, the parent of golden/), the render options
// that override the scene's own, which image of the render it keeps (the render, or an
// adaptive render's sample map), the pixel hash of its reference image golden/NAME.exr,
// and how it is compared: exactly (the default) or, where the entry says why, within a
// metric tolerance.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "io/json_reader.h"
#include "io/output_batch.h"
#include "options/render_options.h"
#include "scene/scene.h"

namespace tracer {

// idiff-style thresholds (compare.h) and the reason a golden cannot be exact.
struct GoldenTolerance {
  float fail = 0.0f;
  float failpercent = 0.0f;
  std::string why;
};

// Which image a golden keeps: the rendered image, or an adaptive render's per-pixel sample
// counts (render/adaptive_film.h), "image": "sample-map" in the manifest.
enum class GoldenImage { Render, SampleMap };

struct GoldenEntry {
  std::string name;   // [a-z0-9-]+: the test and the file name
  std::string scene;  // relative to the source root
  RenderOptions options;
  GoldenImage image = GoldenImage::Render;
  std::string hash;                          // pixel_hash of the reference; empty for a new entry
  std::optional<GoldenTolerance> tolerance;  // nullopt: exact
};

struct GoldenManifest {
  std::string path;                  // ROOT/golden/manifest.json
  std::string root;                  // the source root
  std::vector<GoldenEntry> entries;  // sorted by name

  std::string image_path(const GoldenEntry& e) const;      // ROOT/golden/NAME.exr
  std::string scene_path(const GoldenEntry& e) const;      // ROOT/SCENE
  const GoldenEntry& find(const std::string& name) const;  // InputError when absent
};

// A golden's options as overrides of its scene, whose messages name the manifest and the
// entry ("golden/manifest.json: goldens.ball.options.spp"), not the command line.
inline RenderOverrides golden_overrides(const GoldenManifest& manifest, const GoldenEntry& e) {
  RenderOverrides o{e.options};
  o.origin = manifest.path + ": goldens." + e.name + ".options";
  return o;
}

std::string manifest_path(const std::string& root);
GoldenManifest read_manifest(const std::string& root);                    // InputError naming file and key
void add_manifest(OutputBatch& outputs, const GoldenManifest& manifest);  // in a stable layout, on commit

}  // namespace tracer
