// `tracer-gpu bench`'s rays table (docs/cuda.md): the three ray sets of `tracer bench rays`
// (bench/ray_sets.h) on a bundle's scene, traced by the runner's CPU threads and, on a GPU,
// by the stream schedule's closest-hit and shadow kernels on bvh's binary tree (its nodes, and
// its pair records) and on its 8-wide tree; every row's hits are checked against the CPU's.
#pragma once
#include <string>

#include "bundle/scene_bundle.h"

namespace tracer {

// The most triangles with_generated_mesh makes: the scene loader's limit.
constexpr uint32_t kMostGeneratedTriangles = 1u << 24;

// `bundle`'s scene with its primitives replaced by generate_mesh(kind, triangles)
// (bench/mesh_generators.h) under a SAH bvh built as the tracer builds it (accel/bvh_builder.h):
// a mesh too large to carry in a bundle, the 10^6-triangle terrain; the bundle gives the camera
// and the settings. InputError for an unknown kind or a bundle without a material.
SceneBundle with_generated_mesh(SceneBundle bundle, const std::string& kind, uint32_t triangles);

// Prints the table's rows for `bundle` (a bvh scene), `label` naming it. The 8-wide tree is
// collapsed here from the bundle's binary tree, as the tracer collapses it. InputError when the
// bundle's structure is not bvh; std::runtime_error when a row's hits differ from the CPU's.
void run_ray_bench(const SceneBundle& bundle, const std::string& label, bool gpu, unsigned threads, uint32_t repeats);

}  // namespace tracer
