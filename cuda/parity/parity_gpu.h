// The GPU side of the CUDA parity cases (parity_gpu.cu): each call copies the inputs to
// the device, runs one kernel that applies a parity_cases.h function to every input, and
// copies the answers back. DeviceUnavailable when there is no usable GPU.
#pragma once
#include <string>
#include <vector>

#include "parity_cases.h"
#include "scene/scene_arrays.h"

namespace tracer::parity {

std::string gpu_device();  // the device the calls run on
std::vector<float> gpu_math(MathFunction f, const std::vector<float>& a, const std::vector<float>& b);
std::vector<Philox4> gpu_philox(const std::vector<PhiloxQuery>& queries);
std::vector<ShapeAnswer> gpu_shapes(const std::vector<ShapeQuery>& queries);
std::vector<TraceAnswer> gpu_trace(const SceneArrays& arrays, const SceneView& view, const std::vector<Ray>& rays);
std::vector<BsdfAnswer> gpu_bsdfs(const std::vector<BsdfQuery>& queries);
std::vector<AdaptiveAnswer> gpu_adaptive(const std::vector<AdaptiveQuery>& queries);
std::vector<SampleAnswer> gpu_samples(const SceneArrays& arrays, const SceneView& view);  // every pixel, in index order
// Every sample's radiance (pixel-major) from the stream schedule's stage kernels.
std::vector<Vec3> gpu_stream_samples(const SceneArrays& arrays, const SceneView& view);

}  // namespace tracer::parity
