// The rays `tracer bench rays` and `tracer-gpu bench`'s rays table trace: primary rays through
// the pixel centres of a film, incoherent rays (origins uniform in a box, directions uniform
// on the sphere, Philox with a fixed seed, so every machine makes the same), and shadow rays
// from each primary hit toward a light. Header-only kernel code, for the tracer and the runner.
#pragma once
#include <cstdint>
#include <vector>

#include "kernel/base/philox.h"
#include "kernel/geom/ray_offset.h"
#include "kernel/shading/sampling.h"
#include "kernel/shading/surface.h"

namespace tracer {

struct RaySets {
  std::vector<Ray> primary, incoherent, shadow;
  std::vector<float> shadow_tmax;
};

inline RaySets make_primary_and_incoherent_rays(const Camera& camera, uint32_t width, uint32_t height, Vec3 lo, Vec3 hi,
                                                uint32_t incoherent) {
  RaySets r;
  r.primary.reserve(static_cast<size_t>(width) * height);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) r.primary.push_back(camera_ray(camera, x + 0.5f, y + 0.5f, 0.5f, 0.5f));
  r.incoherent.reserve(incoherent);
  for (uint32_t i = 0; i < incoherent; ++i) {
    float u[6];
    for (uint32_t d = 0; d < 3; ++d) sample_uniform2(0x5EEDu, i, 0, d, u[2 * d], u[2 * d + 1]);
    const Vec3 o = {lo.x + u[0] * (hi.x - lo.x), lo.y + u[1] * (hi.y - lo.y), lo.z + u[2] * (hi.z - lo.z)};
    r.incoherent.push_back({o, direction_from(1.0f - 2.0f * u[3], u[4])});
  }
  return r;
}

// Where `tracer bench rays` puts the camera for a bare mesh (an OBJ file): looking at the
// centre of the mesh's box [lo, hi] from 1.2 diagonals along (0.5, 0.6, 1), 45 degrees.
inline Vec3 mesh_bench_eye(Vec3 lo, Vec3 hi) {
  return (lo + hi) * 0.5f + normalize(Vec3{0.5f, 0.6f, 1.0f}) * (1.2f * length(hi - lo));
}
constexpr float kMeshBenchFov = 45.0f;

// The light shadow rays aim at: above the camera by its distance to the image plane's corner.
inline Vec3 shadow_light(const Camera& camera) {
  return camera.origin + Vec3{0.0f, length(camera.origin - camera.focal_top_left), 0.0f};
}

// A shadow ray from each primary hit (primary_hits[i] of rays.primary[i]) toward `light`.
inline void add_shadow_rays(const SceneView& view, Vec3 light, const std::vector<Hit>& primary_hits, RaySets& rays) {
  for (size_t i = 0; i < primary_hits.size(); ++i) {
    if (primary_hits[i].prim == kNoHit) continue;
    const Surface s = surface_at(view, rays.primary[i], primary_hits[i]);
    const Vec3 dir = normalize(light - s.p);
    const Ray r = {offset_ray_origin(s.p, s.ng, dir, view.offset_scale), dir};
    rays.shadow.push_back(r);
    rays.shadow_tmax.push_back(length(light - r.origin));
  }
}

// A checksum of the hits (FNV-style): every structure and device must give the same.
inline uint64_t ray_hits_checksum(const std::vector<Hit>& primary, const std::vector<Hit>& incoherent,
                                  const std::vector<uint8_t>& occluded) {
  const auto mix = [](uint64_t h, uint64_t v) { return (h ^ v) * 0x100000001B3ull; };
  uint64_t sum = 0;
  for (const auto* hits : {&primary, &incoherent})
    for (const Hit& h : *hits) sum = mix(mix(sum, h.prim), bits_of(h.t));
  for (uint8_t o : occluded) sum = mix(sum, o);
  return sum;
}

}  // namespace tracer
