// The microfacet material the kernel-level tests evaluate and sample: a coloured albedo, glass
// of ior 1.5 with a white tint, and metal_rough with all three of its lobes in use.
#pragma once
#include "kernel/material/material.h"

namespace tracer::test {

inline Material microfacet_material(MaterialKind kind, float roughness) {
  Material m{};
  m.kind = kind;
  m.roughness = roughness;
  m.albedo = {0.9f, 0.6f, 0.3f};
  m.tint = {1, 1, 1};
  m.ior = 1.5f;
  m.metallic = 0.3f;
  m.transmission = 0.5f;
  return m;
}

}  // namespace tracer::test
