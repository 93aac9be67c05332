// Unidirectional path tracing of the rendering equation (Kajiya 1986) with next-event
// estimation and multiple importance sampling by the power heuristic (Veach 1997): at
// every non-specular vertex one light sample and one BSDF sample, each weighted against
// the other's density; emission reached by a BSDF sample after a specular bounce, or with
// `nee` off (the plain estimator), counts fully. Russian roulette from rr_depth bounces on
// survives with q = min(max throughput / first_throughput, 1) and divides by q, so it stays
// unbiased: the throughput relative to the first vertex's (the pixel's own albedo), so a dark
// surface the camera sees keeps its indirect light as long as a white one (docs/path.md).
// The environment sampled as a light (render.sky_sampling) is MIS-weighted like the shapes.
// With render.mirror_images a non-specular vertex also samples one light through one flat
// mirror (kernel/shading/mirror_images.h), weighted against the BSDF sample that reaches the
// light off that mirror; it draws two more pairs, at dimensions past every bounce's four.
// Random numbers per bounce b: the pairs of PathPair at dimensions kDimFirstFree + kPathPairs b
// + pair, and with mirror images those of MirrorPair past every bounce's, drawn by the scene's
// sampler (sampler.h: Philox pairs, or scrambled Sobol pairs for `sobol`).
#pragma once
#include "kernel/camera/sampler.h"
#include "kernel/geom/ray_offset.h"
#include "kernel/integrator/mirror_image_query.h"
#include "kernel/integrator/whitted.h"
#include "kernel/light/light.h"
#include "kernel/material/bsdf.h"
#include "kernel/shading/surface.h"

namespace tracer {

// The pairs of random numbers one path vertex draws, each at kDimFirstFree + kPathPairs *
// depth + its index; a pair is drawn only where it is read.
enum PathPair : uint32_t {
  kPairLightPoint,          // the point on the light
  kPairLightChoiceAndLobe,  // the light table's choice; the BSDF's lobe or Fresnel choice
  kPairBsdfDirection,       // the BSDF sample's direction
  kPairRouletteAndSkyCell,  // Russian roulette; the environment's cell
  kPathPairs
};

// With mirror images, at kDimMirrorImages + kMirrorPairs * depth + its index.
enum MirrorPair : uint32_t {
  kPairImageChoice,  // the light and the mirror
  kPairImagePoint,   // the point on the light
  kMirrorPairs
};

// A path between two vertices: what the loop carries from one bounce to the next, beside the
// ray and the radiance every integrator's state has. The megakernel keeps it in registers
// (PathState); the stream schedule in one array per field between stages (StreamStates,
// kernel/integrator/stream.h), loaded and stored by load_path and store_path. Listed once:
// X(type in PathState, type in the stream's array, name, its value at the camera ray).
#define TRACER_PATH_STATE(X)                                                                 \
  X(Vec3, Vec3, throughput, (Vec3{1.0f, 1.0f, 1.0f}))                                        \
  /* the previous shading point, where shape_light_pdf must be evaluated exactly as          \
     sample_light saw it for the MIS weights to sum to 1 */                                  \
  X(Vec3, Vec3, from, camera_ray.origin)                                                     \
  X(float, float, bsdf_pdf, 0.0f) /* the density of the BSDF sample that chose ray */        \
  X(uint32_t, uint32_t, depth, 0u)                                                           \
  /* the camera ray or a specular bounce: emission it sees counts fully */                   \
  X(bool, uint8_t, specular, true)                                                           \
  /* max throughput after the first vertex's BSDF sample: roulette's unit */                 \
  X(float, float, first_throughput, 1.0f)                                                    \
  /* the planar mirror the ray just left, reached from a non-specular vertex (whose from and \
     bsdf_pdf the state keeps) when mirror images are sampled; else kNoHit */                \
  X(uint32_t, uint32_t, mirror, kNoHit)

struct PathState {
  Ray ray;
  Vec3 radiance;
#define TRACER_PATH_FIELD(Type, Stored, name, initial) Type name;
  TRACER_PATH_STATE(TRACER_PATH_FIELD)
#undef TRACER_PATH_FIELD
};

// What one shading step leaves to do.
struct PathStep {
  bool shadow;  // trace `shadow` and add its contribution if the light is visible
  bool mirror;  // trace `image` (mirror images) and add its contribution if the way is clear
  bool alive;   // trace state.ray next
};

// The first dimension of the mirror-image pairs of bounce 0: past the pairs of every bounce.
constexpr uint32_t kDimMirrorImages = kDimFirstFree + kPathPairs * kMaxDepth;

TRACER_HD PathState path_start(const Ray& camera_ray) {
  PathState st;
  st.ray = camera_ray;
  st.radiance = {0.0f, 0.0f, 0.0f};
#define TRACER_PATH_START(Type, Stored, name, initial) st.name = initial;
  TRACER_PATH_STATE(TRACER_PATH_START)
#undef TRACER_PATH_START
  return st;
}

// One vertex of the path: `hit` is the closest hit of st.ray. Adds the emission it sees,
// draws the light sample (into shadow) and the BSDF sample (the next st.ray). Compiled without
// kFeatureMirrorImages in kFeatures it draws no image sample and keeps no mirror for one: the
// code a scene without flat mirrors runs.
template <uint32_t kFeatures = TRACER_KERNEL_FEATURES>
TRACER_HD_STEP PathStep path_shade(const SceneView& scene, uint32_t pixel, uint32_t sample, const Hit& hit,
                                   PathState& st, ShadowQuery& shadow, MirrorQuery& image, RayCounts& counts) {
  constexpr bool kImages = (kFeatures & kFeatureMirrorImages) != 0u;
  const RenderSettings& rs = scene.settings;
  const bool nee = rs.nee == Switch::On && scene.light_entry_count > 0;
  PathStep step = {false, false, false};
  if (hit.prim == kNoHit) {
    const float w = nee && !st.specular && scene.environment_light != kNoHit
                        ? power_heuristic(st.bsdf_pdf, environment_light_pdf(scene, st.ray.dir))
                        : 1.0f;
    st.radiance += st.throughput * background_radiance(scene, st.ray.dir) * w;
    if (uses_feature(scene.features, kFeatureDeclaredLights))
      st.radiance += st.throughput * declared_lights_seen(scene, st.ray.dir, nee && !st.specular, st.bsdf_pdf);
    return step;
  }
  Surface s = surface_at(scene, st.ray, hit);
  const Material m = material_at(scene, s);  // may bend s.ns by a normal or bump map
  const bool front = dot(st.ray.dir, s.ng) < 0.0f;
  if (emits(m) && (front || m.two_sided)) {
    float w = 1.0f;
    if (nee && !st.specular)
      w = power_heuristic(st.bsdf_pdf,
                          shape_light_pdf(scene, hit.prim, st.from, st.ray.dir, length(s.p - st.from), s.ng));
    else if (kImages && nee && st.mirror != kNoHit)
      w = power_heuristic(st.bsdf_pdf, mirror_image_pdf(scene, st.mirror, hit.prim, st.from, st.ray.dir, s.p, s.ng));
    st.radiance += st.throughput * m.radiance * w;
  }
  if (st.depth >= rs.max_depth) return step;
  const Vec3 wo = -st.ray.dir;
  const Vec3 n = front ? s.ns : -s.ns;
  const uint32_t dim = kDimFirstFree + kPathPairs * st.depth;
  const bool sample_lights = nee && !is_specular(m);
  const bool roulette = st.depth + 1 >= rs.rr_depth;
  // An image sample only where the mirror's vertex may still bounce, as a BSDF path could.
  const bool sample_images = kImages && sample_lights && scene.mirror_count > 0 && st.depth + 1u < rs.max_depth;
  // A pair is drawn only where it is read (a Lambert vertex lit by one light reads no light
  // choice and no lobe choice): each is a pure function of its dimension, so one left undrawn
  // changes no other.
  float light_u1 = 0.0f, light_u2 = 0.0f, pick_u = 0.0f, choice_u = 0.0f, dir_u1 = 0.0f, dir_u2 = 0.0f, rr_u = 0.0f,
        sky_cell_u = 0.0f, image_pick_u = 0.0f, mirror_u = 0.0f, image_u1 = 0.0f, image_u2 = 0.0f;
  if (sample_lights) draw_uniform2(rs.sampler, rs.seed, pixel, sample, dim + kPairLightPoint, light_u1, light_u2);
  if ((sample_lights && scene.light_entry_count > 1) || bsdf_uses_choice(m))
    draw_uniform2(rs.sampler, rs.seed, pixel, sample, dim + kPairLightChoiceAndLobe, pick_u, choice_u);
  if (!is_specular(m)) draw_uniform2(rs.sampler, rs.seed, pixel, sample, dim + kPairBsdfDirection, dir_u1, dir_u2);
  if (roulette || (sample_lights && scene.environment_light != kNoHit))
    draw_uniform2(rs.sampler, rs.seed, pixel, sample, dim + kPairRouletteAndSkyCell, rr_u, sky_cell_u);
  if (sample_images) {
    const uint32_t image_dim = kDimMirrorImages + kMirrorPairs * st.depth;
    draw_uniform2(rs.sampler, rs.seed, pixel, sample, image_dim + kPairImageChoice, image_pick_u, mirror_u);
    draw_uniform2(rs.sampler, rs.seed, pixel, sample, image_dim + kPairImagePoint, image_u1, image_u2);
  }

  if (sample_lights) {
    const LightSample ls = sample_light(scene, pick_light(scene, pick_u), s.p, light_u1, light_u2, sky_cell_u);
    const BsdfValue f = ls.valid ? eval_bsdf(m, wo, ls.wi, n, front) : BsdfValue{{0.0f, 0.0f, 0.0f}, 0.0f};
    if (max_component(f.f_cos) > 0.0f) {
      ++counts.shadow;
      const float w = ls.delta ? 1.0f : power_heuristic(ls.pdf, f.pdf);
      shadow = shadow_query(scene, s, ls);
      shadow.contribution = st.throughput * f.f_cos * ls.radiance * (w / ls.pdf);
      step.shadow = true;
    }
  }
  if (sample_images) {
    const MirrorImageSample is = sample_mirror_image(scene, s.p, image_pick_u, mirror_u, image_u1, image_u2);
    const BsdfValue f = is.valid ? eval_bsdf(m, wo, is.wi, n, front) : BsdfValue{{0.0f, 0.0f, 0.0f}, 0.0f};
    if (max_component(f.f_cos) > 0.0f) {
      counts.shadow += 2u;
      image = mirror_query(scene, s, is);
      image.to_mirror.contribution = st.throughput * f.f_cos * is.radiance * (power_heuristic(is.pdf, f.pdf) / is.pdf);
      step.mirror = true;
    }
  }

  BsdfSample bs;
  if (!sample_bsdf(m, wo, n, front, choice_u, dir_u1, dir_u2, bs)) return step;
  st.throughput *= bs.weight;
  // A mirror reached from a non-specular vertex keeps that vertex's from and bsdf_pdf for the
  // image's MIS weight where the light is hit next.
  const bool off_image_mirror = kImages && scene.mirror_count > 0 && bs.specular && !st.specular &&
                                is_planar_mirror(scene, scene.primitives[hit.prim]);
  st.mirror = off_image_mirror ? hit.prim : kNoHit;
  if (!off_image_mirror) st.bsdf_pdf = bs.pdf;
  st.specular = bs.specular;
  // the floor keeps the ratio finite after a first vertex that absorbs almost everything
  if (st.depth == 0u) st.first_throughput = max_of(max_component(st.throughput), 1e-3f);
  if (roulette) {
    const float q = min_of(max_component(st.throughput) / st.first_throughput, 1.0f);
    if (!(rr_u < q)) return step;
    st.throughput = st.throughput / q;
  }
  st.ray = {offset_ray_origin(s.p, s.ng, bs.wi, scene.offset_scale), bs.wi};
  if (!off_image_mirror) st.from = s.p;
  ++st.depth;
  ++counts.secondary;
  step.alive = true;
  return step;
}

// The megakernel: the whole path in one call, each shadow ray traced where it is drawn.
template <uint32_t kFeatures = TRACER_KERNEL_FEATURES>
TRACER_HD Vec3 path_radiance(const SceneView& scene, const Ray& camera_ray, uint32_t pixel, uint32_t sample,
                             RayCounts& counts) {
  constexpr uint32_t kCode = full_trace_code<kFeatures>();
  PathState st = path_start(camera_ray);
  for (;;) {
    const Hit hit = trace_closest<kCode>(scene, st.ray, kInfinity);
    ShadowQuery shadow;
    MirrorQuery image;
    const PathStep step = path_shade<kFeatures>(scene, pixel, sample, hit, st, shadow, image, counts);
    const uint8_t kinds = static_cast<uint8_t>((step.shadow ? unsigned{kShadowLight} : 0u) |
                                               (step.mirror ? unsigned{kShadowMirror} : 0u));
    const uint8_t clear = trace_shadows<kCode>(scene, kinds, shadow, &image, 0);
    if (clear & kShadowLight) st.radiance += shadow.contribution;
    if (clear & kShadowMirror) st.radiance += image.to_mirror.contribution;
    if (!step.alive) return st.radiance;
  }
}

}  // namespace tracer
