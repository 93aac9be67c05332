// The scene as kernel code sees it: plain pointers to flat arrays, filled on the host
// (and, later, on the device). Closest-hit and any-hit queries dispatch on the
// acceleration structure with a switch; every structure returns the same hit, because the
// closest hit is the minimum of (t, primitive id) compared lexicographically (DESIGN.md rule 4).
#pragma once
#include "bvh_node.h"
#include "camera.h"
#include "features.h"
#include "material.h"
#include "plane.h"
#include "primitive.h"
#include "quad.h"
#include "sampler.h"
#include "sphere.h"
#include "triangle.h"

namespace tracer {

enum class AccelKind : uint32_t { Bvh, None };
enum class IntegratorKind : uint32_t { Whitted, Normals, Albedo, Depth, Path };
enum class BackgroundKind : uint32_t { Constant, Gradient };

struct PointLight {
  Vec3 position;
  Vec3 intensity;
  float kc, kl, kq;         // attenuation, used when has_attenuation
  uint32_t has_attenuation;  // 0: physical 1/d^2 falloff
};

// An entry of the path integrator's light table (kernel/light_sampling.h).
enum class LightKind : uint32_t { Point, Shape };
struct LightEntry {
  LightKind kind;
  uint32_t index;  // into SceneView::lights, or the emitting primitive's id
  float pmf;       // probability of choosing this light
  float cdf;       // sum of the pmfs up to and including this entry; 1 for the last
};

struct Background {
  BackgroundKind kind;
  Vec3 radiance;  // constant; the zenith colour for gradient
  Vec3 horizon;   // gradient only
};

// Whitted effects that can be switched off to measure their cost (`--effects`, `tracer
// bench device`). Off, shadows let every light through; reflection and refraction rays
// (including a dielectric's Fresnel reflection) are not traced.
enum EffectBit : uint32_t { kEffectShadows = 1u, kEffectReflection = 2u, kEffectRefraction = 4u, kEffectAll = 7u };

struct RenderSettings {
  IntegratorKind integrator;
  SamplerKind sampler;
  AccelKind accel;
  uint32_t spp;
  uint32_t grid_n;  // sqrt(spp) for grid and stratified
  uint32_t max_depth;
  uint64_t seed;
  uint32_t width, height;
  uint32_t effects;  // EffectBit mask; kEffectAll unless a benchmark says otherwise
  uint32_t nee;      // path: next-event estimation with MIS (1) or the plain estimator (0)
  uint32_t rr_depth; // path: Russian roulette from this many bounces on
};

struct SceneView {
  const Primitive* primitives;
  uint32_t primitive_count;
  const TriangleShading* triangle_shading;
  const uint32_t* bounded;    // ids of primitives with finite bounds (BVH leaves index it)
  uint32_t bounded_count;
  const uint32_t* unbounded;  // ids of planes, tested for every ray
  uint32_t unbounded_count;
  const BvhNode* bvh_nodes;
  uint32_t bvh_node_count;
  const Material* materials;
  const PointLight* lights;
  uint32_t light_count;
  const LightEntry* light_table;  // path integrator: every light with its selection probability
  uint32_t light_entry_count;
  const uint32_t* light_of_prim;  // per primitive: its light_table entry, or kNoHit
  Background background;
  Vec3 ambient;
  Camera camera;
  RenderSettings settings;
  uint32_t features;  // FeatureBit mask
};

struct Hit {
  float t;
  uint32_t prim;  // kNoHit when nothing was hit
  float b1, b2;   // triangle barycentrics of v1, v2 | quad (alpha, beta)
};
constexpr uint32_t kNoHit = 0xffffffffu;

// Tests one primitive; keeps it when (t, id) is below the best so far.
TRACER_HD void test_primitive(const SceneView& scene, uint32_t id, const Ray& ray,
                              const RayShear& shear, Hit& best) {
  const Primitive& p = scene.primitives[id];
  float t = 0.0f, b0 = 0.0f, b1 = 0.0f, b2 = 0.0f;
  bool hit = false;
  switch (p.kind) {
    case ShapeKind::Sphere: hit = intersect_sphere(p.a, p.radius, ray, 0.0f, best.t, t); break;
    case ShapeKind::Plane: hit = intersect_plane(p.a, p.b, ray, 0.0f, best.t, t); break;
    case ShapeKind::Triangle:
      hit = intersect_triangle(p.a, p.b, p.c, ray, shear, 0.0f, best.t, t, b0, b1, b2);
      break;
    case ShapeKind::Quad: hit = intersect_quad(p.a, p.b, p.c, ray, 0.0f, best.t, t, b1, b2); break;
  }
  if (hit && (t < best.t || id < best.prim)) best = {t, id, b1, b2};
}

// Closest hit with t in (0, tmax].
TRACER_HD Hit trace_closest(const SceneView& scene, const Ray& ray, float tmax) {
  Hit best = {tmax, kNoHit, 0.0f, 0.0f};
  const RayShear shear = make_ray_shear(ray.dir);
  for (uint32_t i = 0; i < scene.unbounded_count; ++i)
    test_primitive(scene, scene.unbounded[i], ray, shear, best);
  switch (scene.settings.accel) {
    case AccelKind::None:
      for (uint32_t i = 0; i < scene.bounded_count; ++i)
        test_primitive(scene, scene.bounded[i], ray, shear, best);
      break;
    case AccelKind::Bvh: {
      if (scene.bvh_node_count == 0) break;
      const Vec3 inv = inverse_direction(ray.dir);
      uint32_t stack[64];
      int top = 0;
      uint32_t node = 0;
      float t_enter;
      if (!ray_box(scene.bvh_nodes[0].lo, scene.bvh_nodes[0].hi, ray.origin, inv, 0.0f, best.t, t_enter))
        break;
      for (;;) {
        const BvhNode& n = scene.bvh_nodes[node];
        if (n.count > 0) {
          for (uint32_t i = 0; i < n.count; ++i)
            test_primitive(scene, scene.bounded[n.first + i], ray, shear, best);
        } else {
          // Visit the nearer child first; a child is pruned only when it starts strictly
          // beyond the best hit, so a tie at equal t can still be won by a smaller id.
          float t_left, t_right;
          const BvhNode& l = scene.bvh_nodes[n.first];
          const BvhNode& r = scene.bvh_nodes[n.first + 1];
          const bool hit_l = ray_box(l.lo, l.hi, ray.origin, inv, 0.0f, best.t, t_left);
          const bool hit_r = ray_box(r.lo, r.hi, ray.origin, inv, 0.0f, best.t, t_right);
          if (hit_l && hit_r) {
            const bool left_first = t_left <= t_right;
            stack[top++] = left_first ? n.first + 1 : n.first;
            node = left_first ? n.first : n.first + 1;
            continue;
          }
          if (hit_l || hit_r) {
            node = hit_l ? n.first : n.first + 1;
            continue;
          }
        }
        // Pop the next node that can still hold a hit no farther than the best.
        bool found = false;
        while (top > 0) {
          node = stack[--top];
          const BvhNode& c = scene.bvh_nodes[node];
          if (ray_box(c.lo, c.hi, ray.origin, inv, 0.0f, best.t, t_enter)) {
            found = true;
            break;
          }
        }
        if (!found) break;
      }
      break;
    }
  }
  return best;
}

// Any hit with t in (0, tmax): the shadow-ray query. The answer is a property of the set
// of primitives, so the order of visits cannot change it.
TRACER_HD bool trace_any(const SceneView& scene, const Ray& ray, float tmax) {
  // Ask for t <= the float just below tmax: a hit exactly at the light does not occlude.
  const float limit = float_of_bits(bits_of(tmax) - 1u);
  Hit probe = {limit, kNoHit, 0.0f, 0.0f};
  const RayShear shear = make_ray_shear(ray.dir);
  for (uint32_t i = 0; i < scene.unbounded_count; ++i) {
    test_primitive(scene, scene.unbounded[i], ray, shear, probe);
    if (probe.prim != kNoHit) return true;
  }
  switch (scene.settings.accel) {
    case AccelKind::None:
      for (uint32_t i = 0; i < scene.bounded_count; ++i) {
        test_primitive(scene, scene.bounded[i], ray, shear, probe);
        if (probe.prim != kNoHit) return true;
      }
      return false;
    case AccelKind::Bvh: {
      if (scene.bvh_node_count == 0) return false;
      const Vec3 inv = inverse_direction(ray.dir);
      uint32_t stack[64];
      int top = 0;
      stack[top++] = 0;
      while (top > 0) {
        const BvhNode& n = scene.bvh_nodes[stack[--top]];
        float t_enter;
        if (!ray_box(n.lo, n.hi, ray.origin, inv, 0.0f, limit, t_enter)) continue;
        if (n.count > 0) {
          for (uint32_t i = 0; i < n.count; ++i) {
            test_primitive(scene, scene.bounded[n.first + i], ray, shear, probe);
            if (probe.prim != kNoHit) return true;
          }
        } else {
          stack[top++] = n.first + 1;
          stack[top++] = n.first;
        }
      }
      return false;
    }
  }
  return false;
}

}  // namespace tracer
