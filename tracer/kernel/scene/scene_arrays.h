// Every flat array a SceneView points to, listed once (the idea of Blender Cycles'
// kernel/data_arrays.h). X(Type, name) declares SceneView::name as `const Type*`; the host
// expands the same list into Scene's vectors and Scene::view (tracer/scene/scene_arrays.h), the
// device upload (cuda/device_scene.h) and the scene bundle (tracer/bundle/scene_bundle.h), so an array
// added here reaches all of them and none can hand a host pointer to the GPU.
#pragma once

#define TRACER_SCENE_ARRAYS(X)                                                                       \
  X(Primitive, primitives)             /* every shape, by primitive id */                            \
  X(TriangleShading, triangle_shading) /* per triangle: normals, uvs, tangents */                    \
  X(uint32_t, bounded)                 /* ids of primitives with finite bounds, in BVH leaf order */ \
  X(uint32_t, unbounded)               /* ids of planes, tested for every ray */                     \
  X(BvhNode, bvh_nodes)                /* bvh and lbvh */                                            \
  X(BvhPairNode, bvh_pairs)            /* the GPU's walk of bvh_nodes: built at upload, else empty */ \
  X(PairTriangle, bvh_pair_triangles)  /* their leaves' triangles */                                 \
  X(WideBvhNode, wide_nodes)           /* bvh on the CPU: the 8-wide collapse of bvh_nodes */        \
  X(TriangleBlock, triangle_blocks)    /* its leaves' primitives, 4 to a block */                    \
  X(KdNode, kd_nodes)                  /* kdtree and kdtree-median */                                \
  X(uint32_t, kd_prims)                                                                              \
  X(uint32_t, grid_cell_start) /* grid: first entry of each cell in grid_prims */                    \
  X(uint32_t, grid_prims)                                                                            \
  X(Material, materials)                                                                             \
  X(Texture, textures)       /* kernel/shading/texture.h */                                          \
  X(float, texels)           /* image textures' linear RGB */                                        \
  X(Light, lights)           /* the declared lights (kernel/light/light_records.h) */                \
  X(LightEntry, light_table) /* path: every light with its selection probability */                  \
  X(uint32_t, light_of_prim) /* per primitive: its light_table entry, or kNoHit */                   \
  X(SkyCell, sky_cells)      /* environment: 6 faces x n x n, face-major then row-major */           \
  X(uint32_t, mirror_prims)  /* path with mirror_images: the planar mirrors' primitive ids */
