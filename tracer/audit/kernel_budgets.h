// The resource budget of every CUDA kernel of the tracer on sm_90 (docs/cuda.md, "Resource
// budgets"): registers per thread, stack frame and spilled bytes per thread, static shared
// memory per block. `tracer audit resources` (test audit.resources, label determinism) fails
// when a kernel exceeds its row or has none. `block` is the kernel's launch width, for the
// occupancy docs/cuda.md derives. A row is lowered when a change frees resources, and raised
// only by a commit that says why.
#pragma once
#include <string>

namespace tracer {

struct KernelBudget {
  const char* kernel;  // kernel_name(): "path_render_kernel"; a template keeps its arguments
  int registers, stack_bytes, spill_bytes, shared_bytes;
  int block;  // threads per block at launch
};

// clang-format off: a table, aligned by hand
inline constexpr KernelBudget kKernelBudgets[] = {
    // kernel                            registers stack spill shared block
    // the megakernel, one per integrator (cuda/gpu_film.cu), 16x16 blocks
    // path: two more for the Sobol scramble seeds' 64-bit SplitMix64 words, two fewer since the
    // GPU reverses bits with brev and draws only the pairs a vertex reads; 34 more for mirror
    // images (kernel/shading/mirror_images.h: the image's light sample and its query live across
    // the light's shadow ray), 12.5 % occupancy throughout. Every kernel holding a SceneView copy
    // has 16 bytes more stack for its mirror_prims and mirror_count. Lowered (2026-11-27) when
    // the texture filter's edge texels stopped taking an integer remainder, and again when lights
    // went through one dispatch (kernel/light/light.h); 3 more when materials did
    // (kernel/material/bsdf.h: a struct per kind), in the same occupancy step. Mirror images are
    // a kernel feature (kFeatureMirrorImages) since 2026-11-27: a scene without a flat mirror runs
    // the path kernels compiled without them (183 -> 155 registers here, 12.5 % still). Spot
    // lights and suns (kernel/light/spot_light.h, directional_light.h): path 155 -> 156 (the
    // miss meets a sun's disc), Whitted 182 -> 184 (the declared light's kind switch), 12.5 % still.
    // 16 bytes more stack in every kernel holding a SceneView copy since it points at the binary
    // tree's pair records (bvh_pairs, bvh_pair_triangles, bvh_pair_count; 2026-11-27), and 288
    // more in every kernel running the full trace code since the GPU's full code walks them too
    // (kernel/accel/traverse_bvh_pairs.h: its stack of (record, entry distance)); registers in
    // the same occupancy steps: path 156, its adaptive pass 146 -> 147, Whitted 184 -> 182,
    // views 86 -> 84 and their adaptive pass 78 -> 80, the parity trace kernel 88 -> 92.
    // The equirectangular environment map (kernel/light/equirect_map.h, 2026-11-27): 16 bytes
    // more stack where a SceneView is copied (its cells' rows, the map and its turn), path
    // 156 -> 158 and 183 -> 187 registers (the map's lookup and sampling in the miss and the
    // light choice), their adaptive passes 147 -> 146 and 170 -> 173, the path shade stages
    // 124 -> 126 and 149 -> 163, the parity sample kernel 203 -> 201: every kernel in the same
    // occupancy step (12.5 %, 18.75 % and 25 %).
    // Cut-outs (kernel/accel/alpha_test.h, 2026-11-27): every code that traces with kTraceAlpha
    // reads a hit's material and its alpha map before keeping the hit: path 158 -> 162, Whitted
    // 182 -> 192, views 84 -> 88, the path adaptive pass 146 -> 150, Whitted's 172 -> 176, the path
    // shade stage 126 -> 128, the full-code stages 70 -> 72 (the closest-hit stage at its cap of 72
    // spills 28 bytes), the parity kernels 92 -> 96 and 201 -> 208; the mirror-image kernels 1 to
    // 5 fewer. Every kernel stays in its occupancy step. The trace variants hold no alpha code:
    // a scene with a cut-out runs the full-code stages.
    // Cut-outs compiled out of the megakernels of scenes without one (2026-11-28; the
    // *_alpha_* kernels keep them): path 160 -> 156, Whitted 190 -> 179, the adaptive passes
    // 152 -> 144 and 176 -> 168 (Whitted's 12.5 % -> 18.75 % occupancy). With this change ptxas
    // spills more in two shadow variants at their 64-register cap: the binary tree's 0 -> 12
    // bytes, the 8-wide tree's 12 -> 72 (80 before this round's NaN-ray check).
    // An image texture's times and plus (kernel/shading/texture.h, 2026-11-28: a use's factor
    // applied after filtering, so one image under many tints is stored once) in every lookup:
    // the stream's path shade stage 122 -> 128 and views' 46 -> 48, the sphere shadow stages
    // 57-60 -> 61 (a mirror image's textured light), the closest-hit stage's spills 28 -> 36
    // bytes (its alpha test, at the cap of 72); every kernel in its occupancy step, the
    // megakernels unchanged.
    // The grid's walk without its step array (kernel/accel/traverse_grid.h, 2026-11-28: a step is
    // the direction's sign where it is used): the grid variants 53 -> 46 (spheres) and 64 -> 62
    // registers, their stacks 24-32 -> 0-16 bytes and closest_hit_grid_triangles' 4 spilled bytes
    // gone; the full-code stages' spills 36 -> 12; the Whitted megakernels 6 fewer, the alpha
    // path kernels 4-5 fewer; two adaptive path passes 1 and 4 more (145, 185), each in its
    // occupancy step.
    // render.stream_order (2026-11-30; the stream's hosts read it, no kernel does) makes the
    // settings in every SceneView copy 4 bytes longer: 16 bytes more stack in the path and
    // Whitted megakernels and adaptive passes and 8 in the path shade stages, as their copies'
    // alignment rounds it; registers unchanged.
    {"path_render_kernel",               156, 1136, 0, 0, 256},
    {"path_alpha_render_kernel",         156, 1136, 0, 0, 256},
    {"path_mirror_images_render_kernel", 193, 1136, 0, 0, 256},
    {"whitted_render_kernel",            173, 3776, 0, 0, 256},
    {"whitted_alpha_render_kernel",      184, 3776, 0, 0, 256},
    {"view_render_kernel",                88,  560, 0, 0, 256},
    // adaptive sampling (cuda/gpu_adaptive.cu)
    // path: mirror images, as the megakernel (18.75 % occupancy -> 12.5 %)
    // without mirror images 145 (18.75 %), with them 171 (12.5 %); 146 with spot lights and suns.
    // 145 -> 148 and 147 -> 148 (2026-11-28) when a vertex's shadow queries took their image query
    // by index (kernel/integrator/mirror_image_query.h), in the same occupancy step
    {"path_adaptive_pass_kernel",        148, 1136, 0, 0, 128},
    {"path_alpha_adaptive_pass_kernel",  148, 1136, 0, 0, 128},
    {"path_mirror_images_adaptive_pass_kernel", 185, 1136, 0, 0, 128},
    {"whitted_adaptive_pass_kernel",     168, 3776, 0, 0, 128},
    {"whitted_alpha_adaptive_pass_kernel", 172, 3776, 0, 0, 128},
    {"view_adaptive_pass_kernel",         80,  560, 0, 0, 128},
    {"mark_unconverged_kernel",           40,    0, 0, 0, 128},
    {"keep_kernel",                       16,    0, 0, 0, 128},
    // the stream schedule (cuda/gpu_stream.cu)
    {"begin_batch_kernel",                20,    0, 0, 0, 128},
    {"generate_stage_kernel",             24,    0, 0, 0, 128},
    {"closest_hit_stage_kernel",          72,  576, 12, 0, 128},
    // one register more for render.light_sampling's solid-angle branch, one for Russian
    // roulette's first-vertex throughput and five for spherical triangles (Arvo's sample), in
    // the same occupancy step (25 %); 43 more and a stack frame for mirror images (25 % -> 18.75 %);
    // three more when lights went through one dispatch (kernel/light/light.h: a light sample
    // carries its delta flag and emitter), one more for the materials' dispatch, in the same
    // occupancy step. Without mirror images' code 124 (25 %); with it 149 (18.75 %)
    {"path_shade_stage_kernel",          128,  768, 0, 0, 128},
    {"path_mirror_images_shade_stage_kernel", 163, 768, 0, 0, 128},
    // Whitted and views: seven and one more for emission from any material (glTF's), the
    // normal map's bitangent sign and per-axis texture wrap; both within the 8-register
    // allocation step they were in (96 and 48), so occupancy is unchanged
    {"whitted_shade_stage_kernel",        96,    0, 0, 0, 128},
    {"view_shade_stage_kernel",           48,    0, 0, 0, 128},
    {"shadow_any_hit_stage_kernel",       72,  560, 0, 0, 128},
    // the trace variants' stages (kernel/accel/trace_variants.h), held to 64 registers; each shadow
    // stage traces a mirror image's two ways too (trace_shadows: one traversal call site), so the
    // sphere variants' shadow stages hold more. Since 2026-11-28 a structure's leaves test with
    // leaf_trace_code (no plane test: planes are unbounded), which freed the registers the 8-wide
    // closest-hit kernel spilled (76 bytes -> 0) and the sphere rows' (4 to 7 fewer); the grid's
    // triangle rows took 2 and 1 more, the 8-wide shadow row spills 34 bytes (12 before): ptxas's
    // choices at the 64-register cap.
    // The binary tree walked through its pair records (kernel/accel/traverse_bvh_pairs.h): a stack
    // of (record, entry distance), 512 bytes; 2.2x the node walk's primary and 2.0x its incoherent
    // rays on an H200 (docs/cuda.md). The walk alone since 2026-11-28 (kTraceBvhPairs: a tree
    // without records runs the wide tree's row, which holds the node walk): no spills (12 bytes
    // in the closest-hit kernel before, with the node walk beside it)
    // Since 2026-11-28 the 8-wide walk returns where its tree is deeper than its stack and
    // trace_into walks the binary tree from there (one call site of the node walk, not two):
    // the 8-wide closest-hit stack 1088 -> 848 bytes, its shadow row's spills 34 -> 8 bytes. A
    // vertex's shadow queries hold their legs in one pending mask and read the image query by
    // index, not through a pointer (kernel/integrator/mirror_image_query.h): the last 8 bytes
    // gone, every shadow row 2 to 5 registers fewer (the sphere rows 50 % -> 56.25 % occupancy)
    {"closest_hit_bvh_triangles_kernel",  64,  560, 0, 0, 128},
    {"shadow_any_hit_bvh_triangles_kernel", 62, 560, 0, 0, 128},
    // the 8-wide tree: its 64-entry stack, the binary walk's for a deeper tree or none
    {"closest_hit_wide_bvh_triangles_kernel", 64, 848, 0, 0, 128},
    {"shadow_any_hit_wide_bvh_triangles_kernel", 64, 1072, 0, 0, 128},
    {"closest_hit_bvh_spheres_kernel",    48,  272, 0, 0, 128},
    {"shadow_any_hit_bvh_spheres_kernel", 56,  272, 0, 0, 128},
    {"closest_hit_kdtree_triangles_kernel", 64,  0, 0, 0, 128},
    {"shadow_any_hit_kdtree_triangles_kernel", 64, 0, 0, 0, 128},
    {"closest_hit_kdtree_spheres_kernel", 43,    0, 0, 0, 128},
    {"shadow_any_hit_kdtree_spheres_kernel", 56,  0, 0, 0, 128},
    {"closest_hit_grid_triangles_kernel", 64,   16, 0, 0, 128},
    {"shadow_any_hit_grid_triangles_kernel", 60, 16, 0, 0, 128},
    {"closest_hit_grid_spheres_kernel",   43,   16, 0, 0, 128},
    {"shadow_any_hit_grid_spheres_kernel", 56,   0, 0, 0, 128},
    {"split_kernel",                      17,    0, 0, 0, 128},
    {"end_batch_kernel",                  28,    0, 0, 0, 128},
    // the LBVH build (cuda/lbvh_gpu.cu)
    {"key_kernel",                        13,    0, 0, 0, 256},
    {"radix_kernel",                      20,    0, 0, 0, 256},
    {"gather_kernel",                     24,    0, 0, 0, 256},
    {"climb_kernel",                      30,    0, 0, 0, 256},
    // the rays' sort keys before a sorted trace (cuda/ray_order_gpu.cu)
    {"ray_order_key_kernel",              18,    0, 0, 0, 256},
    // parity cases (cuda/parity/parity_gpu.cu)
    {"math_kernel",                       29,    0, 0, 0, 256},
    {"philox_kernel",                     18,    0, 0, 0, 256},
    {"shape_kernel",                      42,    0, 0, 0, 256},
    {"bsdf_kernel",                       56,    0, 0, 0, 256},
    {"adaptive_kernel",                   46,    0, 0, 0, 256},
    // the leaves' tests without a plane's (leaf_trace_code, 2026-11-28): 96 -> 90
    {"trace_kernel",                      90,  560, 0, 0, 256},
    // the path tracer's sample, with mirror images; one more for per-axis texture wrap
    {"sample_kernel",                    208, 3200, 0, 0, 256},
};
// clang-format on

inline const KernelBudget* find_kernel_budget(const std::string& name) {
  for (const KernelBudget& b : kKernelBudgets)
    if (name == b.kernel) return &b;
  return nullptr;
}

}  // namespace tracer
