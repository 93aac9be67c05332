// A mesh's triangles as the scene's primitives, through a transform: the JSON scene's meshes
// (shape_reader.cpp) and glTF meshes (gltf_scene.cpp) alike. Per-vertex tangents are computed
// where the mesh has uvs and none were given (mesh_tangents.h); triangles without a geometric
// normal (zero area, or a normal that under- or overflows a float) are left out and counted.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "scene/mesh.h"
#include "scene/scene.h"
#include "scene/transform.h"

namespace tracer {

// Whether normalize(cross(e1, e2)), as surface.h computes a triangle's or quad's normal,
// is a finite unit vector.
bool has_unit_normal(Vec3 e1, Vec3 e2);

// Appends one primitive per kept triangle (materials[i] for tris[i]); returns how many were
// kept. `zero_normal` is called (and must throw) when a vertex normal is zero; a non-finite
// transformed corner is an InputError naming the scene file.
size_t append_mesh_triangles(Scene& scene, std::vector<MeshTriangle> tris, const Transform& xf,
                             const std::vector<uint32_t>& materials, const std::function<void()>& zero_normal);

// Appends a primitive after checking its coordinates are finite.
void append_primitive(Scene& scene, const Primitive& p);

}  // namespace tracer
