// Unidirectional path tracing of the rendering equation (Kajiya 1986) with next-event
// estimation and multiple importance sampling by the power heuristic (Veach 1997): at
// every non-specular vertex one light sample and one BSDF sample, each weighted against
// the other's density; emission reached by a BSDF sample after a specular bounce, or with
// `nee` off (the plain estimator), counts fully. Russian roulette from rr_depth bounces on
// survives with q = min(max throughput, 0.95) and divides by q, so it stays unbiased.
// A cube-map sky sampled as a light (render.sky_sampling) is MIS-weighted like the shapes.
// Random numbers per bounce b: four pairs at dimensions kDimFirstFree + 4b + {0..3} (light
// position; light choice and BSDF lobe; BSDF direction; roulette and sky cell), drawn by the
// scene's sampler (sampler.h: Philox pairs, or scrambled Sobol pairs for `sobol`).
#pragma once
#include "kernel/camera/sampler.h"
#include "kernel/geom/ray_offset.h"
#include "kernel/integrator/whitted.h"
#include "kernel/shading/bsdf.h"
#include "kernel/shading/light_sampling.h"
#include "kernel/shading/surface.h"

namespace tracer {

// Whether the shading point at s sees the sampled light (a point light within its
// distance, the sky past everything, an emitter as the closest hit along wi).
TRACER_HD bool light_visible(const SceneView& scene, const Surface& s, const LightSample& ls) {
  const Ray ray = {offset_ray_origin(s.p, s.ng, ls.wi, scene.offset_scale), ls.wi};
  if (ls.prim == kSkyLight) return !trace_any(scene, ray, kInfinity);
  if (ls.prim == kNoHit) return !trace_any(scene, ray, length(s.p + ls.wi * ls.distance - ray.origin));
  return trace_closest(scene, ray, kInfinity).prim == ls.prim;
}

TRACER_HD Vec3 path_radiance(const SceneView& scene, Ray ray, uint32_t pixel, uint32_t sample, RayCounts& counts) {
  const RenderSettings& rs = scene.settings;
  const bool nee = rs.nee == Switch::On && scene.light_entry_count > 0;
  Vec3 radiance = {0.0f, 0.0f, 0.0f}, throughput = {1.0f, 1.0f, 1.0f};
  float bsdf_pdf = 0.0f;
  bool specular = true;    // the camera ray: emission it sees counts fully
  Vec3 from = ray.origin;  // the previous shading point, where light_pdf must be evaluated
                           // exactly as sample_light saw it for the MIS weights to sum to 1
  for (uint32_t depth = 0;; ++depth) {
    const Hit hit = trace_closest(scene, ray, kInfinity);
    if (hit.prim == kNoHit) {
      const float w = nee && !specular && scene.sky_light != kNoHit
                          ? power_heuristic(bsdf_pdf, sky_light_pdf(scene, ray.dir))
                          : 1.0f;
      radiance += throughput * background_radiance(scene, ray.dir) * w;
      break;
    }
    Surface s = surface_at(scene, ray, hit);
    const Material m = material_at(scene, s);  // may bend s.ns by a normal or bump map
    const bool front = dot(ray.dir, s.ng) < 0.0f;
    if (m.kind == MaterialKind::Emissive && (front || m.two_sided)) {
      const float w =
          nee && !specular
              ? power_heuristic(bsdf_pdf, light_pdf(scene, hit.prim, from, ray.dir, length(s.p - from), s.ng))
              : 1.0f;
      radiance += throughput * m.radiance * w;
    }
    if (depth >= rs.max_depth) break;
    const Vec3 wo = -ray.dir;
    const Vec3 n = front ? s.ns : -s.ns;
    const uint32_t dim = kDimFirstFree + 4u * depth;
    const bool sample_lights = nee && !is_specular(m);
    const bool roulette = depth + 1 >= rs.rr_depth;
    // A pair is drawn only where it is used: each is a pure function of its dimension, so
    // one left undrawn changes no other.
    float light_u1 = 0.0f, light_u2 = 0.0f, pick_u, choice_u, dir_u1, dir_u2, rr_u = 0.0f, sky_cell_u = 0.0f;
    if (sample_lights) draw_uniform2(rs.sampler, rs.seed, pixel, sample, dim, light_u1, light_u2);
    draw_uniform2(rs.sampler, rs.seed, pixel, sample, dim + 1u, pick_u, choice_u);
    draw_uniform2(rs.sampler, rs.seed, pixel, sample, dim + 2u, dir_u1, dir_u2);
    if (roulette || (sample_lights && scene.sky_light != kNoHit))
      draw_uniform2(rs.sampler, rs.seed, pixel, sample, dim + 3u, rr_u, sky_cell_u);

    if (sample_lights) {
      const LightSample ls = sample_light(scene, pick_light(scene, pick_u), s.p, light_u1, light_u2, sky_cell_u);
      const BsdfValue f = ls.valid ? eval_bsdf(m, wo, ls.wi, n) : BsdfValue{{0.0f, 0.0f, 0.0f}, 0.0f};
      if (max_component(f.f_cos) > 0.0f) {
        ++counts.shadow;
        if (light_visible(scene, s, ls)) {
          const float w = ls.prim == kNoHit ? 1.0f : power_heuristic(ls.pdf, f.pdf);
          radiance += throughput * f.f_cos * ls.radiance * (w / ls.pdf);
        }
      }
    }

    BsdfSample bs;
    if (!sample_bsdf(m, wo, n, front, choice_u, dir_u1, dir_u2, bs)) break;
    throughput *= bs.weight;
    bsdf_pdf = bs.pdf;
    specular = bs.specular;
    if (roulette) {
      const float q = min_of(max_component(throughput), 0.95f);
      if (!(rr_u < q)) break;
      throughput = throughput / q;
    }
    ray = {offset_ray_origin(s.p, s.ng, bs.wi, scene.offset_scale), bs.wi};
    from = s.p;
    ++counts.secondary;
  }
  return radiance;
}

}  // namespace tracer
