// Watertightness of the ray/triangle test on a closed mesh: rays from points inside the mesh
// aimed at every vertex and at points along every edge must all hit something (a ray from
// inside a closed surface cannot leave without crossing it); a miss is a ray that slipped
// through a crack between two triangles. Used by `tracer bench watertight` and the
// extremes tests, for the watertight test and for Moller-Trumbore.
#pragma once
#include <string>
#include <vector>

#include "scene/scene.h"

namespace tracer {

struct WatertightProbe {
  uint64_t rays = 0;
  uint64_t escapes = 0;     // rays that hit nothing
  uint32_t open_edges = 0;  // edges not shared by exactly two triangles: 0 for a closed mesh
  double seconds = 0.0;     // tracing only
};

// Loads the OBJ as a one-mesh scene (bvh) with the given triangle test.
Scene load_probe_mesh(const std::string& obj_path, TriangleTest triangle_test);

// Origins: the centre of the mesh's bounds and points around it at 1/8 of its size, kept
// when rays both ways along each axis cross the mesh an odd number of times (inside; one
// way only would take a point just beside an open sheet for an inside one). Throws
// InputError when none is inside.
std::vector<Vec3> inside_points(const Scene& mesh);

// Every origin to every vertex and to `edge_points` evenly spaced points of every edge
// (ends excluded).
WatertightProbe probe_watertight(const Scene& mesh, const std::vector<Vec3>& origins, uint32_t edge_points,
                                 int threads);

}  // namespace tracer
