// A scene bundle: everything the kernel reads to render one scene (every array of
// kernel/scene/scene_arrays.h with decoded textures and sky tables, the view's scalars with the
// camera and render settings, the sample range), written by `tracer bundle` and rendered
// by the GPU runner without the loaders. Sections of a "scene" BundleFile: "view" (one
// SceneView, pointers zero), "samples" (one SampleRange), "source" (the scene and options
// it came from, for messages) and one section per array, named as in the list.
#pragma once
#include <string>

#include "bundle_file.h"
#include "kernel/base/sample_range.h"
#include "scene/scene_arrays.h"

namespace tracer {

struct SceneBundle {
  SceneArrays arrays;
  SceneView scalars{};  // every pointer null; counts follow the arrays
  SampleRange range;
  std::string source;

  SceneView view() const {
    SceneView v = scalars;
    point_view_at(v, arrays);
    return v;
  }
};

// The bundle leaves bvh's 8-wide tree out (its reader walks the binary tree, the same hits,
// and the bundle is about half the size) unless `keep_wide_tree`: a device that reads it then
// walks the wide tree (cuda/device_scene.h).
SceneBundle make_scene_bundle(const SceneArrays& arrays, const SceneView& view, SampleRange range,
                              const std::string& source, bool keep_wide_tree = false);
BundleFile encode_scene_bundle(const SceneBundle& bundle);
// InputError naming `path`: a missing section, another build's layout, an empty or
// oversized image, a sample range outside [0, spp).
SceneBundle decode_scene_bundle(const BundleFile& file, const std::string& path);
SceneBundle read_scene_bundle(const std::string& path);

}  // namespace tracer
