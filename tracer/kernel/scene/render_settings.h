// The render settings kernel code reads, listed once (the model: Cycles' kernel/data_arrays.h).
// Each TRACER_RENDER_OPTIONS entry X(name, Type, default, section, recorded, help) is a field
// of RenderSettings here and, on the host (options/render_options.h), the scene file's key
// `section.name`, the command-line flag --name (underscores as dashes), the key `name` of a
// golden's manifest entry, a partial file's identity and --stats, and the help text. A
// setting added here reaches all of them; what is left to write is its use in the kernel, and
// for a new enum its names (options/enum_names.h) and its bound in options/settings_check.h
// (which a scene bundle's reader applies too).
// `recorded` says when an identity records the option: Always, PathTracer (the path
// integrator only), PathTracerUnderEnvironmentLight, or UnlessDefault.
#pragma once
#include "kernel/camera/sampler.h"

namespace tracer {

enum class AccelKind : uint32_t { Bvh, None, Kdtree, KdtreeMedian, Grid, Lbvh };
enum class IntegratorKind : uint32_t { Whitted, Normals, Albedo, Depth, Path };
enum class TriangleTest : uint32_t { Watertight, MollerTrumbore };
enum class Switch : uint32_t { Off, On };
// How next-event estimation samples a rectangular or triangular light: uniformly by area, or
// uniformly in the solid angle it subtends (kernel/shading/spherical_rectangle.h,
// spherical_triangle.h; docs/path.md says when each pays).
enum class LightSampling : uint32_t { Area, SolidAngle };
// How the CPU or GPU walks the samples (the same image either way): one call per pixel
// sample (render_pixel.h), or ray states in queues, one stage at a time (stream.h).
enum class Schedule : uint32_t { Megakernel, Stream };
// The order the stream schedule traces each wave's secondary and shadow rays in (the same
// image either way): the queues' own, or sorted by their rays' origin and direction cells
// (kernel/geom/ray_order_key.h), so that rays traced side by side walk the same nodes.
enum class StreamOrder : uint32_t { Queue, Sorted };
constexpr uint32_t kMaxStreamWidth = 1u << 24;  // samples in flight (about 2 to 4 GB of ray states)

// Whitted effects that can be switched off to measure their cost (`--effects`, `tracer
// bench device`): a mask of these bits. Off, shadows let every light through; reflection and
// refraction rays (including a dielectric's Fresnel reflection) are not traced.
enum Effects : uint32_t {
  kEffectNone = 0u,
  kEffectShadows = 1u,
  kEffectReflection = 2u,
  kEffectRefraction = 4u,
  kEffectAll = 7u
};

#define TRACER_RENDER_OPTIONS(X)                                                                                    \
  X(integrator, IntegratorKind, IntegratorKind::Whitted, render, Always, "whitted, path, normals, albedo or depth") \
  X(sampler, SamplerKind, SamplerKind::Sobol, render, Always, "center, grid, stochastic, stratified or sobol")      \
  X(spp, uint32_t, 1u, render, Always, "samples per pixel")                                                         \
  X(seed, uint64_t, 0u, render, Always, "64-bit seed")                                                              \
  X(width, uint32_t, 0u, film, Always, "image width in pixels")                                                     \
  X(height, uint32_t, 0u, film, Always, "image height in pixels")                                                   \
  X(accel, AccelKind, AccelKind::Bvh, render, Always, "bvh (default), kdtree, kdtree-median, grid, lbvh or none")   \
  X(max_depth, uint32_t, 5u, render, Always, "maximum ray depth")                                                   \
  X(nee, Switch, Switch::On, render, PathTracer,                                                                    \
    "path: next-event estimation with MIS, on (default) or off (the plain estimator)")                              \
  X(rr_depth, uint32_t, 3u, render, PathTracer, "path: Russian roulette from this many bounces on (default 3)")     \
  X(sky_sampling, Switch, Switch::On, render, PathTracerUnderEnvironmentLight,                                      \
    "path: sample a cube-map sky as a light, on (default) or off (only BSDF rays find it)")                         \
  X(light_sampling, LightSampling, LightSampling::Area, render, UnlessDefault,                                      \
    "path: rectangle and triangle lights sampled by area (default) or solid-angle (uniform in their solid angle)")  \
  X(mirror_images, Switch, Switch::On, render, UnlessDefault,                                                       \
    "path: also sample the lights seen in flat mirrors, as their mirror images, on (default) or off (only BSDF "    \
    "rays find them)")                                                                                              \
  X(triangle_test, TriangleTest, TriangleTest::Watertight, render, UnlessDefault,                                   \
    "watertight (default) or moller-trumbore")                                                                      \
  X(grid_resolution, uint32_t, 0u, render, UnlessDefault,                                                           \
    "grid: cells along the longest axis (default 0: about 3 per primitive)")                                        \
  X(effects, Effects, kEffectAll, render, UnlessDefault,                                                            \
    "Whitted effects to trace: all (default), none, or a list of shadows,reflections,refractions")                  \
  X(noise_threshold, float, 0.0f, render, UnlessDefault,                                                            \
    "adaptive sampling: a pixel stops once its estimated relative error is below this (default: off, every pixel "  \
    "takes spp)")                                                                                                   \
  X(min_spp, uint32_t, 16u, render, UnlessDefault,                                                                  \
    "adaptive sampling: the samples every pixel takes before it may stop (default 16, or spp if less)")             \
  X(target_error, float, 0.0f, render, UnlessDefault,                                                               \
    "stop the render at the first checkpoint (min_spp, doubling) where the image's estimated relative RMS error "   \
    "is below this, or at spp (default: off)")                                                                      \
  X(schedule, Schedule, Schedule::Megakernel, render, Never,                                                        \
    "megakernel (default: a pixel sample per call) or stream (ray states in queues, a stage at a time); the same "  \
    "image")                                                                                                        \
  X(stream_width, uint32_t, 1u << 18, render, Never, "stream: the pixel samples in flight (default 262144)")     \
  X(stream_order, StreamOrder, StreamOrder::Queue, render, Never,                                                   \
    "stream: trace each wave's secondary and shadow rays in queue order (default) or sorted by origin and "         \
    "direction; the same image")

struct RenderSettings {
#define TRACER_SETTING_FIELD(name, Type, default_value, ...) Type name = default_value;
  TRACER_RENDER_OPTIONS(TRACER_SETTING_FIELD)
#undef TRACER_SETTING_FIELD
  uint32_t grid_n = 1;  // sqrt(spp) for the grid and stratified samplers (derived from spp)
};

// Whether the settings ask for adaptive sampling (docs/path.md): per pixel (noise_threshold)
// or for the whole image (target_error).
inline bool adaptive_render(const RenderSettings& rs) { return rs.noise_threshold > 0.0f || rs.target_error > 0.0f; }

}  // namespace tracer
