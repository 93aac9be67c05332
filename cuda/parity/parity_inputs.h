// The inputs of the CPU/GPU parity cases, generated from a seed by integer arithmetic
// (SplitMix64) and kernel functions only, so every machine builds the same inputs: the
// GoogleTest parity tests and the GPU pack (`tracer gpu-pack`, cuda/runner/) share them,
// and a pack carries a seed and a count instead of hundreds of megabytes of queries.
#pragma once
#include <cfloat>
#include <limits>
#include <vector>

#include "accel/lbvh_build.h"
#include "parity_cases.h"

namespace tracer::parity {

struct Inputs {
  uint64_t state;
  uint64_t next() {  // SplitMix64 (Steele, Lea, Flood 2014)
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  float bits() { return float_of_bits(static_cast<uint32_t>(next())); }
  float uniform(float lo, float hi) { return lo + (hi - lo) * static_cast<float>(next() >> 40) * 0x1p-24f; }
  Vec3 in_box(float lo, float hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
  Vec3 direction() {  // uniform on the sphere, by rejection
    for (;;) {
      const Vec3 v = in_box(-1.0f, 1.0f);
      const float l2 = dot(v, v);
      if (l2 > 1e-4f && l2 <= 1.0f) return v / det_sqrt(l2);
    }
  }
};

// Arguments of one math function: every pair of 32 edge values, then `random` pairs of
// random bit patterns, then `domain` points of the function's domain.
struct MathInputs {
  std::vector<float> a, b;
};
inline MathInputs math_inputs(MathFunction f, uint64_t seed, uint32_t random, uint32_t domain) {
  const float edges[] = {0.0f,
                         -0.0f,
                         FLT_TRUE_MIN,
                         -FLT_TRUE_MIN,
                         FLT_MIN,
                         -FLT_MIN,
                         0.5f,
                         -0.5f,
                         1.0f,
                         -1.0f,
                         2.0f,
                         -2.0f,
                         1.5707964f,
                         -1.5707964f,
                         3.1415927f,
                         -3.1415927f,
                         1e-30f,
                         88.72f,
                         -103.9f,
                         1e4f,
                         1e10f,
                         1e30f,
                         16777216.0f,
                         0x1p120f,
                         FLT_MAX,
                         -FLT_MAX,
                         kInfinity,
                         -kInfinity,
                         std::numeric_limits<float>::quiet_NaN(),
                         0.99999994f,
                         1.0000001f,
                         -0.99999994f};
  const float lo[] = {-100, -100, -100, -1, -1, -50, -104, 0, 0}, hi[] = {100, 100, 100, 1, 1, 50, 89, 1e6f, 10};
  const uint32_t fi = static_cast<uint32_t>(f);
  MathInputs in;
  for (float x : edges)
    for (float y : edges) in.a.push_back(x), in.b.push_back(y);
  Inputs g{seed};
  for (uint32_t i = 0; i < random; ++i) in.a.push_back(g.bits()), in.b.push_back(g.bits());
  for (uint32_t i = 0; i < domain; ++i) in.a.push_back(g.uniform(lo[fi], hi[fi])), in.b.push_back(g.uniform(-20, 20));
  return in;
}

// The first half are the renderer's counters (pixel, sample, dimension, 0), the rest random.
inline std::vector<PhiloxQuery> philox_inputs(uint64_t seed, uint32_t count) {
  Inputs in{seed};
  std::vector<PhiloxQuery> q;
  for (uint32_t i = 0; i < count; ++i) {
    const bool structured = i < count / 2;
    q.push_back(
        {{{structured ? i : static_cast<uint32_t>(in.next()), structured ? i % 64 : static_cast<uint32_t>(in.next()),
           structured ? i % 3 : static_cast<uint32_t>(in.next()), structured ? 0u : static_cast<uint32_t>(in.next())}},
         static_cast<uint32_t>(in.next()),
         static_cast<uint32_t>(in.next())});
  }
  return q;
}

// Rays aimed at points on and near each shape: `per_kind` spheres of radius 1e-3 .. 10,
// `per_kind` triangles (inside, on edges with one weight 0, at vertices), per_kind / 4
// quads and planes.
inline std::vector<ShapeQuery> shape_inputs(uint64_t seed, uint32_t per_kind) {
  Inputs in{seed};
  std::vector<ShapeQuery> q;
  const Primitive none = {ShapeKind::Sphere, 0, -1, 0.0f, {}, {}, {}};
  for (uint32_t i = 0; i < per_kind; ++i) {
    Primitive p = none;
    p.a = in.in_box(-10, 10);
    p.radius = det_exp(in.uniform(-6.9f, 2.3f));
    const Vec3 target = p.a + in.direction() * (p.radius * in.uniform(0.9f, 1.1f));
    const Vec3 origin = in.in_box(-20, 20);
    q.push_back({p, {origin, normalize(target - origin)}});
  }
  for (uint32_t i = 0; i < per_kind; ++i) {
    Primitive p = none;
    p.kind = ShapeKind::Triangle;
    p.a = in.in_box(-5, 5), p.b = in.in_box(-5, 5), p.c = in.in_box(-5, 5);
    float u = in.uniform(0, 1), v = in.uniform(0, 1 - u);
    if (i % 4 == 1) v = 0.0f;
    if (i % 4 == 2) u = 1.0f, v = 0.0f;
    const Vec3 target = p.a + (p.b - p.a) * u + (p.c - p.a) * v;
    const Vec3 origin = in.in_box(-20, 20);
    q.push_back({p, {origin, normalize(target - origin)}});
  }
  for (uint32_t i = 0; i < per_kind / 4; ++i) {
    Primitive p = none;
    p.kind = i % 2 ? ShapeKind::Quad : ShapeKind::Plane;
    p.a = in.in_box(-5, 5), p.b = in.in_box(-3, 3), p.c = in.in_box(-3, 3);
    if (p.kind == ShapeKind::Plane) p.b = normalize(p.b);
    const Vec3 target = p.a + p.b * in.uniform(-0.1f, 1.1f) + p.c * in.uniform(-0.1f, 1.1f);
    const Vec3 origin = in.in_box(-20, 20);
    q.push_back({p, {origin, normalize(target - origin)}});
  }
  return q;
}

// Rays with origins uniform in [lo, hi] and directions uniform on the sphere.
inline std::vector<Ray> ray_inputs(uint64_t seed, uint32_t count, Vec3 lo, Vec3 hi) {
  Inputs in{seed};
  std::vector<Ray> rays;
  for (uint32_t i = 0; i < count; ++i) {
    const Vec3 o = {in.uniform(lo.x, hi.x), in.uniform(lo.y, hi.y), in.uniform(lo.z, hi.z)};
    rays.push_back({o, in.direction()});
  }
  return rays;
}

// Half sums of pixels: sample counts from 2 to 2^20 (odd ones too), per-sample means of
// 0 to 2^8 film units scaled to the count, halves that agree exactly, sums of zero, of
// opposite signs and near the film's 2^62 limit, thresholds from 2^-20 to 1e6 and 0 (no
// per-pixel rule).
inline std::vector<AdaptiveQuery> adaptive_inputs(uint64_t seed, uint32_t count) {
  Inputs in{seed};
  std::vector<AdaptiveQuery> q;
  const float thresholds[] = {0.0f, 0x1p-20f, 0.01f, 0.05f, 0.1f, 0.25f, 1.0f, 1e6f};
  for (uint32_t i = 0; i < count; ++i) {
    AdaptiveQuery a{};
    a.samples = 2u + static_cast<uint32_t>(in.next() % (i % 3 == 0 ? 64u : (1u << 20) - 1u));
    const double n_even = static_cast<double>((a.samples + 1u) / 2u), n_odd = static_cast<double>(a.samples / 2u);
    for (int c = 0; c < 3; ++c) {
      const double mean = static_cast<double>(in.next() >> 40) * kFilmUnits * 0x1p-16;  // 0 .. 2^8 per sample
      const double wobble = 1.0 + (static_cast<double>(in.next() >> 11) * 0x1p-53 - 0.5) * 0.5;
      a.even.rgb[c] = static_cast<int64_t>(mean * n_even);
      a.odd.rgb[c] = static_cast<int64_t>(mean * wobble * n_odd);
      switch (i % 8) {
        case 1: a.odd.rgb[c] = static_cast<int64_t>(static_cast<double>(a.even.rgb[c]) / n_even * n_odd); break;
        case 2: a.even.rgb[c] = a.odd.rgb[c] = 0; break;
        case 3: a.odd.rgb[c] = -a.odd.rgb[c]; break;
        case 4: a.even.rgb[c] = kFilmSumLimit - static_cast<int64_t>(in.next() >> 40); break;
        case 5: a.even.rgb[c] = -a.even.rgb[c], a.odd.rgb[c] = -a.odd.rgb[c]; break;
        default: break;
      }
    }
    a.threshold = i % 5 == 4 ? in.uniform(0.0f, 0.5f) : thresholds[in.next() % 8];
    q.push_back(a);
  }
  return q;
}

// Boxes of `count` small random triangles in the unit cube (edges up to 2^-8, every tenth
// sharing its centroid with the one before, so Morton codes tie): an LBVH build's input.
inline LbvhInput lbvh_inputs(uint64_t seed, uint32_t count) {
  Inputs in{seed};
  LbvhInput out;
  for (uint32_t i = 0; i < count; ++i) {
    const Vec3 a = i % 10 == 9 ? out.boxes.back().lo : in.in_box(0.0f, 1.0f);
    const Vec3 b = a + in.in_box(-0x1p-8f, 0x1p-8f), c = a + in.in_box(-0x1p-8f, 0x1p-8f);
    const LbvhBox box = {min_of(a, min_of(b, c)), max_of(a, max_of(b, c))};
    out.boxes.push_back(box);
    out.centroids.push_back((box.lo + box.hi) * 0.5f);
    out.ids.push_back(i);
  }
  return out;
}

// The microfacet materials (conductor with Schlick's and the exact Fresnel, rough glass,
// metal-rough with all three lobes) at random roughness and at its edges (0, either side of
// the smooth threshold, 1), glass of ior 0.5 to 3 and exactly 1, seen from normal to grazing,
// from either side of glass, every tenth from below its normal, with uniforms at 0 and 1-.
inline std::vector<BsdfQuery> bsdf_inputs(uint64_t seed, uint32_t count) {
  Inputs in{seed};
  const MaterialKind kinds[] = {MaterialKind::GgxConductor, MaterialKind::GgxDielectric, MaterialKind::GltfMetalRough};
  const float roughness_edges[] = {0.0f, 0.0099f, kSmoothRoughness, 1.0f};
  const float u_edges[] = {0.0f, 0x1.fffffep-1f};
  const auto u = [&](uint32_t i) { return i % 32 == 5 ? u_edges[in.next() % 2] : in.uniform(0.0f, 1.0f); };
  std::vector<BsdfQuery> q;
  for (uint32_t i = 0; i < count; ++i) {
    BsdfQuery b = {};
    Material& m = b.m;
    m.kind = kinds[i % 3];
    m.fresnel = in.next() % 2 ? FresnelKind::Exact : FresnelKind::Schlick;
    m.roughness = i % 8 == 0 ? roughness_edges[in.next() % 4] : in.uniform(0.0f, 1.0f);
    m.albedo = in.in_box(0.0f, 1.0f), m.tint = in.in_box(0.0f, 1.0f);
    m.eta = in.in_box(0.05f, 3.0f), m.k = in.in_box(0.0f, 8.0f);
    m.metallic = in.uniform(0.0f, 1.0f), m.transmission = in.uniform(0.0f, 1.0f);
    m.ior = i % 16 == 1 ? 1.0f : in.uniform(0.5f, 3.0f);
    for (uint32_t& t : m.texture) t = kNoTexture;
    m.factor_map = m.normal_map = m.bump_map = kNoTexture;
    b.n = in.direction(), b.wo = in.direction(), b.wi_other = in.direction();
    if (i % 10 != 0 && dot(b.wo, b.n) < 0.0f) b.wo = -b.wo;
    if (i % 10 == 1) b.wo = normalize(b.wo - b.n * (dot(b.wo, b.n) - 1e-3f));  // grazing
    b.u_choice = u(i);
    b.u1 = u(i);
    b.u2 = u(i);
    b.front = static_cast<uint32_t>(in.next() % 2);
    q.push_back(b);
  }
  return q;
}

}  // namespace tracer::parity
