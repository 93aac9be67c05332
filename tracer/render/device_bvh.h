// Which of bvh's trees a GPU upload holds (cuda/device_scene.h) and so which one its kernels
// walk: each gives the same hits.
#pragma once

namespace tracer {

enum class DeviceBvh {
  Binary,  // the binary tree's nodes (kernel/accel/traverse_bvh.h)
  Pairs,   // and its pair records where every bounded primitive is a triangle (traverse_bvh_pairs.h)
  Wide,    // and the 8-wide tree (traverse_wide_bvh.h)
};

}  // namespace tracer
