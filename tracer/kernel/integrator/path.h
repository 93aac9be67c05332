// Unidirectional path tracing of the rendering equation (Kajiya 1986) with next-event
// estimation and multiple importance sampling by the power heuristic (Veach 1997): at
// every non-specular vertex one light sample and one BSDF sample, each weighted against
// the other's density; emission reached by a BSDF sample after a specular bounce, or with
// `nee` off (the plain estimator), counts fully. Russian roulette from rr_depth bounces on
// survives with q = min(max throughput / first_throughput, 1) and divides by q, so it stays
// unbiased: the throughput relative to the first vertex's (the pixel's own albedo), so a dark
// surface the camera sees keeps its indirect light as long as a white one (docs/path.md).
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

// A path between two vertices: what the loop carries from one bounce to the next. The
// megakernel keeps it in registers; the stream schedule stores it in arrays between stages.
struct PathState {
  Ray ray;
  Vec3 radiance, throughput;
  Vec3 from;       // the previous shading point, where light_pdf must be evaluated exactly
                   // as sample_light saw it for the MIS weights to sum to 1
  float bsdf_pdf;  // the density of the BSDF sample that chose ray
  uint32_t depth;
  bool specular;           // the camera ray or a specular bounce: emission it sees counts fully
  float first_throughput;  // max throughput after the first vertex's BSDF sample: roulette's unit
};

// Next-event estimation's shadow ray and the radiance it adds when the light is visible.
struct ShadowQuery {
  Ray ray;
  float tmax;        // any-hit test within (0, tmax] (kInfinity for the sky)
  uint32_t emitter;  // kNoHit: the any-hit test; else the emitter the closest hit must be
  Vec3 contribution;
};

// What one shading step leaves to do.
struct PathStep {
  bool shadow;  // trace `shadow` and add its contribution if the light is visible
  bool alive;   // trace state.ray next
};

TRACER_HD PathState path_start(const Ray& camera_ray) {
  return {camera_ray, {0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}, camera_ray.origin, 0.0f, 0u, true, 1.0f};
}

// The shadow ray from the shading point at s to the sampled light: a point light within its
// distance, the sky past everything, an emitter as the closest hit along wi.
TRACER_HD ShadowQuery shadow_query(const SceneView& scene, const Surface& s, const LightSample& ls) {
  const Ray ray = {offset_ray_origin(s.p, s.ng, ls.wi, scene.offset_scale), ls.wi};
  if (ls.prim == kSkyLight) return {ray, kInfinity, kNoHit, {0.0f, 0.0f, 0.0f}};
  if (ls.prim == kNoHit) return {ray, length(s.p + ls.wi * ls.distance - ray.origin), kNoHit, {0.0f, 0.0f, 0.0f}};
  return {ray, kInfinity, ls.prim, {0.0f, 0.0f, 0.0f}};
}

template <uint32_t kCode = kTraceAll>
TRACER_HD bool light_visible(const SceneView& scene, const ShadowQuery& q) {
  // One traversal, any hit or the closest: the kernel holds one copy of it.
  return trace_query<kCode>(scene, q.ray, q.tmax, q.emitter == kNoHit).prim == q.emitter;
}

// One vertex of the path: `hit` is the closest hit of st.ray. Adds the emission it sees,
// draws the light sample (into shadow) and the BSDF sample (the next st.ray).
TRACER_HD_STEP PathStep path_shade(const SceneView& scene, uint32_t pixel, uint32_t sample, const Hit& hit,
                                   PathState& st, ShadowQuery& shadow, RayCounts& counts) {
  const RenderSettings& rs = scene.settings;
  const bool nee = rs.nee == Switch::On && scene.light_entry_count > 0;
  PathStep step = {false, false};
  if (hit.prim == kNoHit) {
    const float w = nee && !st.specular && scene.sky_light != kNoHit
                        ? power_heuristic(st.bsdf_pdf, sky_light_pdf(scene, st.ray.dir))
                        : 1.0f;
    st.radiance += st.throughput * background_radiance(scene, st.ray.dir) * w;
    return step;
  }
  Surface s = surface_at(scene, st.ray, hit);
  const Material m = material_at(scene, s);  // may bend s.ns by a normal or bump map
  const bool front = dot(st.ray.dir, s.ng) < 0.0f;
  if (m.kind == MaterialKind::Emissive && (front || m.two_sided)) {
    const float w =
        nee && !st.specular
            ? power_heuristic(st.bsdf_pdf, light_pdf(scene, hit.prim, st.from, st.ray.dir, length(s.p - st.from), s.ng))
            : 1.0f;
    st.radiance += st.throughput * m.radiance * w;
  }
  if (st.depth >= rs.max_depth) return step;
  const Vec3 wo = -st.ray.dir;
  const Vec3 n = front ? s.ns : -s.ns;
  const uint32_t dim = kDimFirstFree + 4u * st.depth;
  const bool sample_lights = nee && !is_specular(m);
  const bool roulette = st.depth + 1 >= rs.rr_depth;
  // A pair is drawn only where it is read (a Lambert vertex lit by one light reads no light
  // choice and no lobe choice): each is a pure function of its dimension, so one left undrawn
  // changes no other.
  float light_u1 = 0.0f, light_u2 = 0.0f, pick_u = 0.0f, choice_u = 0.0f, dir_u1 = 0.0f, dir_u2 = 0.0f, rr_u = 0.0f,
        sky_cell_u = 0.0f;
  if (sample_lights) draw_uniform2(rs.sampler, rs.seed, pixel, sample, dim, light_u1, light_u2);
  if ((sample_lights && scene.light_entry_count > 1) || bsdf_uses_choice(m))
    draw_uniform2(rs.sampler, rs.seed, pixel, sample, dim + 1u, pick_u, choice_u);
  if (!is_specular(m)) draw_uniform2(rs.sampler, rs.seed, pixel, sample, dim + 2u, dir_u1, dir_u2);
  if (roulette || (sample_lights && scene.sky_light != kNoHit))
    draw_uniform2(rs.sampler, rs.seed, pixel, sample, dim + 3u, rr_u, sky_cell_u);

  if (sample_lights) {
    const LightSample ls = sample_light(scene, pick_light(scene, pick_u), s.p, light_u1, light_u2, sky_cell_u);
    const BsdfValue f = ls.valid ? eval_bsdf(m, wo, ls.wi, n, front) : BsdfValue{{0.0f, 0.0f, 0.0f}, 0.0f};
    if (max_component(f.f_cos) > 0.0f) {
      ++counts.shadow;
      const float w = ls.prim == kNoHit ? 1.0f : power_heuristic(ls.pdf, f.pdf);
      shadow = shadow_query(scene, s, ls);
      shadow.contribution = st.throughput * f.f_cos * ls.radiance * (w / ls.pdf);
      step.shadow = true;
    }
  }

  BsdfSample bs;
  if (!sample_bsdf(m, wo, n, front, choice_u, dir_u1, dir_u2, bs)) return step;
  st.throughput *= bs.weight;
  st.bsdf_pdf = bs.pdf;
  st.specular = bs.specular;
  // the floor keeps the ratio finite after a first vertex that absorbs almost everything
  if (st.depth == 0u) st.first_throughput = max_of(max_component(st.throughput), 1e-3f);
  if (roulette) {
    const float q = min_of(max_component(st.throughput) / st.first_throughput, 1.0f);
    if (!(rr_u < q)) return step;
    st.throughput = st.throughput / q;
  }
  st.ray = {offset_ray_origin(s.p, s.ng, bs.wi, scene.offset_scale), bs.wi};
  st.from = s.p;
  ++st.depth;
  ++counts.secondary;
  step.alive = true;
  return step;
}

// The megakernel: the whole path in one call, each shadow ray traced where it is drawn.
TRACER_HD Vec3 path_radiance(const SceneView& scene, const Ray& camera_ray, uint32_t pixel, uint32_t sample,
                             RayCounts& counts) {
  PathState st = path_start(camera_ray);
  for (;;) {
    const Hit hit = trace_closest(scene, st.ray, kInfinity);
    ShadowQuery shadow;
    const PathStep step = path_shade(scene, pixel, sample, hit, st, shadow, counts);
    if (step.shadow && light_visible(scene, shadow)) st.radiance += shadow.contribution;
    if (!step.alive) return st.radiance;
  }
}

}  // namespace tracer
