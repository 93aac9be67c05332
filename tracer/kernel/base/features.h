// The scene's feature mask (Cycles' KERNEL_FEATURE_* idea): the loader sets a bit for each
// kind of shape, material, light and lens the scene uses, and kernel code skips the paths
// whose bit is clear, so a scene pays only for what it uses. A CPU kernel variant compiled
// for a feature set (tracer/render/cpu_kernel.h) defines TRACER_KERNEL_FEATURES to it, and
// the code of every feature outside the set is compiled out. Code that a GPU kernel may leave
// out takes the mask as a template argument (kFeatures, default TRACER_KERNEL_FEATURES), so one
// .cu file can hold a kernel with the feature and one without (cuda/gpu_film.cu).
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
  kFeatureDeclaredLights = 1u << 9,  // point, spot and directional lights (SceneView::lights)
  kFeatureThinLens = 1u << 10,
  kFeatureShadingNormals = 1u << 11,
  kFeatureTextures = 1u << 12,
  kFeatureMicrofacet = 1u << 13,    // conductor, rough_dielectric, metal_rough
  kFeatureMirrorImages = 1u << 14,  // the path tracer samples lights through flat mirrors (mirror_prims)
  kFeatureAlpha = 1u << 15,         // a shape's material cuts it out (Material::alpha_mode, alpha_test.h)
};

#ifndef TRACER_KERNEL_FEATURES
#define TRACER_KERNEL_FEATURES 0xffffffffu
#endif

// This compilation's features less mirror images: the path kernels for scenes without a flat mirror.
constexpr uint32_t kKernelWithoutMirrorImages = TRACER_KERNEL_FEATURES & ~uint32_t{kFeatureMirrorImages};
// Less cut-outs: the megakernels for scenes without one (their traversal keeps every hit).
constexpr uint32_t kKernelWithoutAlpha = TRACER_KERNEL_FEATURES & ~uint32_t{kFeatureAlpha};
constexpr uint32_t kKernelWithoutMirrorImagesOrAlpha = kKernelWithoutMirrorImages & kKernelWithoutAlpha;

// Whether this compilation of the kernel has code for `feature`.
TRACER_HD constexpr bool compiled_in(uint32_t feature) { return (TRACER_KERNEL_FEATURES & feature) != 0; }

// Whether the scene uses `feature` and this compilation has code for it: a variant is only
// chosen for scenes whose features it holds, so this is the scene's bit wherever it runs.
TRACER_HD bool uses_feature(uint32_t scene_features, uint32_t feature) {
  return compiled_in(feature) && (scene_features & feature) != 0;
}

}  // namespace tracer
