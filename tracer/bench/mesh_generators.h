// Deterministic procedural meshes for the ray benchmarks (`tracer generate`): the same
// arguments give the same OBJ file, byte for byte, on every machine (positions come from
// det_sin/det_cos and integer hashing only).
#pragma once
#include <string>
#include <vector>

#include "scene/mesh.h"

namespace tracer {

// Kinds: terrain (a sine-sum height field), sphere (a displaced UV sphere: the stand-in for
// scanned models such as Lucy and the dragon), boxes (three boxes, 36 triangles), cubes
// (cubes spread through a room), mixed (a displaced sphere among low-polygon cubes), and two
// closed meshes for the watertightness tests: icosphere (20 x 4^k triangles, at most the
// target) and cube (each face a grid of quads). `triangles` is the target count; the result
// is within a few percent of it (boxes: 36; icosphere: the largest 20 x 4^k not above it).
std::vector<MeshTriangle> generate_mesh(const std::string& kind, uint32_t triangles);

const std::vector<std::string>& mesh_generator_kinds();

// Writes an OBJ (v and f lines), atomically.
void write_obj(const std::vector<MeshTriangle>& mesh, const std::string& path);

}  // namespace tracer
