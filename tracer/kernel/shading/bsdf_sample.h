// What a BSDF returns: a sampled direction with its weight, or an evaluated value with its
// density (kernel/material/bsdf.h).
#pragma once
#include "kernel/base/vec3.h"

namespace tracer {

struct BsdfSample {
  Vec3 wi;
  Vec3 weight;  // f |cos| / pdf, or the specular choice's throughput
  float pdf;    // 0 for a specular choice
  bool specular;
};

// f(wo, wi) |cos(n, wi)| and the density with which sample_bsdf picks wi, together.
struct BsdfValue {
  Vec3 f_cos;
  float pdf;
};

// Rec. 709 luminance weights.
TRACER_HD float luminance(Vec3 c) { return dot(Vec3{0.2126f, 0.7152f, 0.0722f}, c); }

}  // namespace tracer
