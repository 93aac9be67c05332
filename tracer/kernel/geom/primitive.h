// Primitives as plain data. A primitive's id is its index in the scene's primitive array,
// fixed by the loader; acceleration structures refer to primitives through an index list
// and never reorder the array, so the (t, id) tie rule cannot depend on the structure.
#pragma once
#include "kernel/base/vec3.h"

namespace tracer {

enum class ShapeKind : uint32_t { Sphere, Plane, Triangle, Quad };

struct Primitive {
  ShapeKind kind;
  uint32_t material;
  int32_t shading;  // triangles: index into the TriangleShading array, or -1
  float radius;     // sphere
  Vec3 a;           // sphere centre | plane point | triangle v0 | quad corner
  Vec3 b;           // plane unit normal | triangle v1 | quad edge u
  Vec3 c;           // triangle v2 | quad edge v
};

// Per-vertex normals and uvs of a mesh triangle (from the OBJ or inline mesh).
struct TriangleShading {
  Vec3 n0, n1, n2;
  float u0, v0, u1, v1, u2, v2;
  Vec3 t0, t1, t2;       // per-vertex tangents, when has_tangents
  float bitangent_sign;  // the bitangent is bitangent_sign * (n x t): -1 where the uvs or the placement mirror
  uint32_t has_normals, has_uvs, has_tangents;
};

}  // namespace tracer
