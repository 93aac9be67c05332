// A mirror image's query (kernel/shading/mirror_images.h: the light sampled through a flat
// mirror) and the shadow queries of one path vertex traced together, the light sample's and the
// image's, from one traversal call site.
#pragma once
#include "kernel/integrator/shadow_query.h"
#include "kernel/shading/mirror_images.h"

namespace tracer {

// A light sampled through a planar mirror: the way to the mirror (its closest hit must be the
// mirror, its emitter) and, from where it meets the mirror along its direction reflected, the
// way to the light (whose closest hit must be `light`); to_mirror's contribution is what the
// light adds when both are clear.
struct MirrorQuery {
  ShadowQuery to_mirror;
  uint32_t light;
};

// Which of a vertex's shadow queries to trace, and which were clear (bits).
enum ShadowKind : uint8_t { kShadowLight = 1u, kShadowMirror = 2u };

// The second way of an image query, from to_mirror's hit at t on the mirror to the light.
TRACER_HD ShadowQuery mirror_to_light(const SceneView& scene, const MirrorQuery& q, float t) {
  const Vec3 n = mirror_normal(scene.primitives[q.to_mirror.emitter]);
  const Vec3 dir = reflect(q.to_mirror.ray.dir, n);
  return {{offset_ray_origin(ray_at(q.to_mirror.ray, t), n, dir, scene.offset_scale), dir},
          kInfinity,
          q.light,
          {0.0f, 0.0f, 0.0f}};
}

// Traces the shadow queries `kinds` names, from one traversal call site (a GPU kernel then holds
// one copy of it): the light sample's, then the image's way to the mirror and, where it gets
// there, on to the light. Returns the bits of those that are clear. The image's query is
// images[index], read only where kinds has kShadowMirror (images may be null otherwise): a GPU
// kernel then holds the index it holds anyway, not a pointer, across the traversal.
template <uint32_t kCode = kTraceAll>
TRACER_HD uint8_t trace_shadows(const SceneView& scene, uint8_t kinds, const ShadowQuery& light,
                                const MirrorQuery* images, uint32_t index) {
  constexpr uint8_t kToLight = 4u;  // the image's second way, after kShadowMirror's first
  uint8_t clear = 0u, pending = kinds & (kShadowLight | kShadowMirror);
  ShadowQuery q;
  if (pending & kShadowLight)
    q = light;
  else if (pending & kShadowMirror)
    q = images[index].to_mirror;
  while (pending != 0u) {  // any hit, or the closest where an emitter must be it
    const Hit h = trace_query<kCode>(scene, q.ray, q.tmax, q.emitter == kNoHit);
    const bool reached = h.prim == q.emitter;
    if (pending & kShadowLight) {
      if (reached) clear |= kShadowLight;
      pending &= ~kShadowLight;
      if (pending != 0u) q = images[index].to_mirror;
    } else if (pending & kShadowMirror) {
      pending = reached ? kToLight : 0u;
      if (reached) q = mirror_to_light(scene, images[index], h.t);
    } else {
      if (reached) clear |= kShadowMirror;
      pending = 0u;
    }
  }
  return clear;
}

// The query for image sample `is` from the shading point at s.
TRACER_HD MirrorQuery mirror_query(const SceneView& scene, const Surface& s, const MirrorImageSample& is) {
  return {{{offset_ray_origin(s.p, s.ng, is.wi, scene.offset_scale), is.wi}, kInfinity, is.mirror, {0.0f, 0.0f, 0.0f}},
          is.light};
}

}  // namespace tracer
