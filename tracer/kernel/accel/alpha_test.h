// Cut-outs: whether a hit on a primitive counts, by its material's alpha (Material::alpha_mode)
// at the hit's texture coordinates (kernel/geom/hit_uv.h). Called by every structure's
// primitive test before it keeps a hit, for closest and any hits alike, so shadows fall through
// the holes. Mask keeps a hit where alpha >= alpha_cutoff; blend keeps it with probability
// alpha, decided by a hash of the ray and the primitive alone (never the order in which a
// structure visits them), so every structure and both devices keep the same hits and the
// closest stays the (t, id) minimum over the hits kept: pbrt-v4's stochastic alpha, with a
// hash of our own.
#pragma once
#include "kernel/accel/trace_code.h"
#include "kernel/geom/hit_uv.h"

namespace tracer {

// MurmurHash3's 32-bit finaliser (Appleby), a bijection that mixes every input bit.
TRACER_HD uint32_t mix_bits(uint32_t h) {
  h ^= h >> 16;
  h *= 0x85ebca6bu;
  h ^= h >> 13;
  h *= 0xc2b2ae35u;
  h ^= h >> 16;
  return h;
}

// A uniform in [0, 1) from the ray's six coordinates and the primitive's id: the same for
// the same (ray, primitive) on every structure, thread and device.
TRACER_HD float blend_uniform(const Ray& ray, uint32_t id) {
  const float words[6] = {ray.origin.x, ray.origin.y, ray.origin.z, ray.dir.x, ray.dir.y, ray.dir.z};
  uint32_t h = mix_bits(id ^ 0x9e3779b9u);
  for (float w : words) h = mix_bits(h ^ bits_of(w));
  return static_cast<float>(h >> 8) * 0x1p-24f;
}

// Whether the hit at (t, b1, b2) on primitive `id` counts, its material read.
TRACER_HD bool cut_out_keeps(const SceneView& scene, uint32_t id, const Ray& ray, float t, float b1, float b2) {
  const Primitive& p = scene.primitives[id];
  const Material& m = scene.materials[p.material];
  if (m.alpha_mode == AlphaMode::Opaque) return true;
  float alpha = m.alpha;
  if (m.alpha_map != kNoTexture) {
    float u, v;
    hit_uv(scene, p, ray, t, b1, b2, u, v);
    alpha *= sample_texture(scene.textures, scene.texels, m.alpha_map, u, v).x;
  }
  return m.alpha_mode == AlphaMode::Mask ? alpha >= m.alpha_cutoff : blend_uniform(ray, id) < alpha;
}

// Whether the hit at (t, b1, b2) on primitive `id` counts. A code without kTraceAlpha
// (trace_code.h) and a scene without kFeatureAlpha keep every hit.
template <uint32_t kCode>
TRACER_HD bool alpha_keeps(const SceneView& scene, uint32_t id, const Ray& ray, float t, float b1, float b2) {
  return !compiled_in(kFeatureAlpha) || !traces<kCode>(kTraceAlpha) || (scene.features & kFeatureAlpha) == 0u ||
         cut_out_keeps(scene, id, ray, t, b1, b2);
}

}  // namespace tracer
