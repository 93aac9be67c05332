// Per-vertex tangents of a triangle mesh with uvs, for normal and bump maps: each
// triangle's dp/du (from its positions and uvs), weighted by its area, summed at every
// vertex it shares (same position and same uv, so uv seams keep separate tangents), then
// normalised. The kernel interpolates them and makes them orthogonal to the shading normal
// (Gram-Schmidt, kernel/shading/surface.h). Each triangle's bitangent_sign makes
// bitangent_sign (n x t) point along dp/dv: -1 where the uvs are mirrored against the side
// the normals face. Triangles whose tangents the file gives (glTF's TANGENT) keep them.
#pragma once
#include <vector>

#include "scene/mesh.h"

namespace tracer {

void compute_vertex_tangents(std::vector<MeshTriangle>& tris);

}  // namespace tracer
