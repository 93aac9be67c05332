// The kernel entry points the CUDA parity tests compare, as plain functions of plain
// inputs. The CPU side of a test calls them directly; the GPU side calls the same
// functions from kernels (parity_kernels.cu). Outputs are compared as bits.
#pragma once
#include "kernel/base/detmath.h"
#include "kernel/base/philox.h"
#include "kernel/integrator/adaptive.h"
#include "kernel/integrator/render_pixel.h"
#include "kernel/material/bsdf.h"

namespace tracer::parity {

enum class MathFunction : uint32_t { Sin, Cos, Tan, Asin, Acos, Atan2, Exp, Log, Pow };
constexpr uint32_t kMathFunctionCount = 9;

TRACER_HD float eval_math(MathFunction f, float a, float b) {
  switch (f) {
    case MathFunction::Sin: return det_sin(a);
    case MathFunction::Cos: return det_cos(a);
    case MathFunction::Tan: return det_tan(a);
    case MathFunction::Asin: return det_asin(a);
    case MathFunction::Acos: return det_acos(a);
    case MathFunction::Atan2: return det_atan2(a, b);
    case MathFunction::Exp: return det_exp(a);
    case MathFunction::Log: return det_log(a);
    case MathFunction::Pow: return det_pow(a, b);
  }
  return 0.0f;
}

struct PhiloxQuery {
  Philox4 counter;
  uint32_t key0, key1;
};

TRACER_HD Philox4 eval_philox(const PhiloxQuery& q) { return philox4x32_10(q.counter, q.key0, q.key1); }

struct ShapeQuery {
  Primitive prim;
  Ray ray;
};

struct ShapeAnswer {
  uint32_t hit;
  float t, b0, b1, b2;
};

// One primitive against one ray over (0, inf), by the same switch the traversal uses.
TRACER_HD ShapeAnswer eval_shape(const ShapeQuery& q) {
  ShapeAnswer r = {0u, 0.0f, 0.0f, 0.0f, 0.0f};
  const Primitive& p = q.prim;
  bool hit = false;
  switch (p.kind) {
    case ShapeKind::Sphere: hit = intersect_sphere(p.a, p.radius, q.ray, 0.0f, kInfinity, r.t); break;
    case ShapeKind::Plane: hit = intersect_plane(p.a, p.b, q.ray, 0.0f, kInfinity, r.t); break;
    case ShapeKind::Triangle:
      hit = intersect_triangle(p.a, p.b, p.c, q.ray, make_ray_shear(q.ray.dir), 0.0f, kInfinity, r.t, r.b0, r.b1, r.b2);
      break;
    case ShapeKind::Quad: hit = intersect_quad(p.a, p.b, p.c, q.ray, 0.0f, kInfinity, r.t, r.b1, r.b2); break;
  }
  r.hit = hit ? 1u : 0u;
  if (!hit) r = {0u, 0.0f, 0.0f, 0.0f, 0.0f};
  return r;
}

struct TraceAnswer {
  Hit closest;
  uint32_t any;
};

// The acceleration structure's closest-hit and any-hit queries for one ray.
TRACER_HD TraceAnswer eval_trace(const SceneView& scene, const Ray& ray) {
  return {trace_closest(scene, ray, kInfinity), trace_any(scene, ray, kInfinity) ? 1u : 0u};
}

struct SampleAnswer {
  FilmSum pixel;
  RayCounts counts;
};

// Every sample of one pixel: the whole integrator, camera to film.
TRACER_HD SampleAnswer eval_sample(const SceneView& scene, uint32_t pixel_index) {
  SampleAnswer a = {{{0, 0, 0}, 0u, 0u}, {0u, 0u, 0u}};
  a.pixel = render_pixel(scene, pixel_index % scene.settings.width, pixel_index / scene.settings.width, 0u,
                         scene.settings.spp, a.counts);
  return a;
}

struct AdaptiveQuery {
  FilmSum even, odd;
  uint32_t samples;
  float threshold;
};

struct AdaptiveAnswer {
  double relative_error;
  uint32_t unconverged, zero;  // `zero` keeps the answer's bytes defined for hashing
};

// Adaptive sampling's per-pixel decision from a pixel's half sums (the estimate in IEEE
// double and the first step of the keep rule; the second step is integer only).
TRACER_HD AdaptiveAnswer eval_adaptive(const AdaptiveQuery& q) {
  return {pixel_relative_error(q.even, q.odd, q.samples),
          static_cast<uint32_t>(pixel_unconverged(q.even, q.odd, q.samples, q.threshold)), 0u};
}

struct BsdfQuery {
  Material m;
  Vec3 wo, n, wi_other;
  float u_choice, u1, u2;
  uint32_t front;
};

struct BsdfAnswer {
  uint32_t sampled, specular;
  Vec3 wi, weight;
  float pdf;
  Vec3 f_cos;  // eval_bsdf in the sampled direction
  float eval_pdf;
  Vec3 f_cos_other;  // and in a direction of the query's own
  float pdf_other;
};

// One material sampled, then evaluated in the sampled direction and in another: the BSDF
// entry points the path tracer and Whitted's direct light call.
TRACER_HD BsdfAnswer eval_bsdf_case(const BsdfQuery& q) {
  BsdfSample s = {{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 0.0f, false};
  BsdfAnswer a = {};
  a.sampled = sample_bsdf(q.m, q.wo, q.n, q.front != 0u, q.u_choice, q.u1, q.u2, s) ? 1u : 0u;
  a.specular = s.specular ? 1u : 0u;
  a.wi = s.wi, a.weight = s.weight, a.pdf = s.pdf;
  const BsdfValue v = eval_bsdf(q.m, q.wo, s.wi, q.n, q.front != 0u);
  a.f_cos = v.f_cos, a.eval_pdf = v.pdf;
  const BsdfValue other = eval_bsdf(q.m, q.wo, q.wi_other, q.n, q.front != 0u);
  a.f_cos_other = other.f_cos, a.pdf_other = other.pdf;
  return a;
}

}  // namespace tracer::parity
