// Every index and size a scene bundle's arrays hold, checked against the arrays they point
// into before any work: a bundle whose checksum matches may still have been edited, and the
// kernels index without bounds checks (a primitive's material, a tree node's children, a
// texture's texels, a light's entry). The trees are walked once from their roots: each node
// reached once, no deeper than the traversals' stacks hold.
#pragma once
#include <string>

#include "scene/scene_arrays.h"

namespace tracer {

// "" when every reference in `arrays` (and the view's own: the environment's light entry, the
// background's textures) points inside its array; else the first that does not, named by its
// array and index ("primitives[3]: material 9 of 2 materials").
std::string bundle_reference_violation(const SceneArrays& arrays, const SceneView& view);

}  // namespace tracer
