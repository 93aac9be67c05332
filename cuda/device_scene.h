// The scene's flat arrays copied to plain device buffers, and a SceneView whose pointers
// point at them: what a kernel receives by value.
#pragma once
#include "device_buffer.h"
#include "scene.h"

namespace tracer {

class DeviceScene {
 public:
  explicit DeviceScene(const Scene& scene)
      : primitives_(scene.primitives),
        triangle_shading_(scene.triangle_shading),
        bounded_(scene.bounded),
        unbounded_(scene.unbounded),
        bvh_nodes_(scene.bvh_nodes),
        materials_(scene.materials),
        lights_(scene.lights),
        light_table_(scene.light_table),
        textures_(scene.textures),
        texels_(scene.texels),
        light_of_prim_(scene.light_of_prim),
        sky_cells_(scene.sky_cells),
        kd_nodes_(scene.kd_nodes),
        kd_prims_(scene.kd_prims),
        grid_cell_start_(scene.grid_cell_start),
        grid_prims_(scene.grid_prims) {
    view_ = scene.view();
    view_.primitives = primitives_.get();
    view_.triangle_shading = triangle_shading_.get();
    view_.bounded = bounded_.get();
    view_.unbounded = unbounded_.get();
    view_.bvh_nodes = bvh_nodes_.get();
    view_.materials = materials_.get();
    view_.lights = lights_.get();
    view_.light_table = light_table_.get();
    view_.textures = textures_.get();
    view_.texels = texels_.get();
    view_.light_of_prim = light_of_prim_.get();
    view_.sky_cells = sky_cells_.get();
    view_.kd_nodes = kd_nodes_.get();
    view_.kd_prims = kd_prims_.get();
    view_.grid_cell_start = grid_cell_start_.get();
    view_.grid_prims = grid_prims_.get();
  }

  const SceneView& view() const { return view_; }

  // Device bytes the arrays take, known before anything is allocated.
  static size_t bytes(const Scene& s) {
    return s.primitives.size() * sizeof(Primitive) + s.triangle_shading.size() * sizeof(TriangleShading) +
           (s.bounded.size() + s.unbounded.size()) * sizeof(uint32_t) + s.bvh_nodes.size() * sizeof(BvhNode) +
           s.materials.size() * sizeof(Material) + s.lights.size() * sizeof(PointLight) +
           s.light_table.size() * sizeof(LightEntry) + s.light_of_prim.size() * sizeof(uint32_t) +
           s.sky_cells.size() * sizeof(SkyCell) +
           s.kd_nodes.size() * sizeof(KdNode) + s.textures.size() * sizeof(Texture) + s.texels.size() * sizeof(float) +
           (s.kd_prims.size() + s.grid_cell_start.size() + s.grid_prims.size()) * sizeof(uint32_t);
  }

 private:
  DeviceBuffer<Primitive> primitives_;
  DeviceBuffer<TriangleShading> triangle_shading_;
  DeviceBuffer<uint32_t> bounded_, unbounded_;
  DeviceBuffer<BvhNode> bvh_nodes_;
  DeviceBuffer<Material> materials_;
  DeviceBuffer<PointLight> lights_;
  DeviceBuffer<LightEntry> light_table_;
  DeviceBuffer<Texture> textures_;
  DeviceBuffer<float> texels_;
  DeviceBuffer<uint32_t> light_of_prim_;
  DeviceBuffer<SkyCell> sky_cells_;
  DeviceBuffer<KdNode> kd_nodes_;
  DeviceBuffer<uint32_t> kd_prims_, grid_cell_start_, grid_prims_;
  SceneView view_{};
};

}  // namespace tracer
