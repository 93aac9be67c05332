// The scene's feature mask (Cycles' KERNEL_FEATURE_* idea): the loader sets a bit for each
// kind of shape, material, light and lens the scene uses, and kernel code skips the paths
// whose bit is clear, so a scene pays only for what it uses.
#pragma once
#include "kernel/base/platform.h"

namespace tracer {

enum FeatureBit : uint32_t {
  kFeatureSphere = 1u << 0,
  kFeaturePlane = 1u << 1,
  kFeatureTriangle = 1u << 2,
  kFeatureQuad = 1u << 3,
  kFeatureLambert = 1u << 4,
  kFeatureMetal = 1u << 5,
  kFeatureDielectric = 1u << 6,
  kFeaturePhong = 1u << 7,
  kFeatureEmissive = 1u << 8,
  kFeaturePointLight = 1u << 9,
  kFeatureThinLens = 1u << 10,
  kFeatureShadingNormals = 1u << 11,
  kFeatureTextures = 1u << 12,
};

}  // namespace tracer
