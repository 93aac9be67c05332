// A glTF 2.0 accessor's elements (specification, section 3.6), read with every offset checked
// against its buffer view and buffer before a byte is read: the six component types,
// normalized integers, byteStride, accessors without a buffer view (zeros) and sparse
// substitution. Errors are InputErrors naming the file and the accessor's JSON path.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
struct BufferView;
}

namespace tracer {

// The most elements an accessor may hold (a mesh attribute of 2^26 vertices is 768 MiB of
// floats): more is refused before anything is allocated.
constexpr uint64_t kMaxGltfAccessorCount = 1ull << 26;

// `components` floats per element, element after element; the accessor's type must have
// exactly that many components. `use` names what refers to it (the JSON path of the key).
std::vector<float> read_gltf_floats(const tinygltf::Model& model, int accessor, int components, const std::string& file,
                                    const std::string& use);

// Empty when the view's bytes lie inside its buffer (view.buffer already checked to name one);
// otherwise "bytes [OFFSET, +LENGTH) lie outside buffer B of N bytes", for the caller's path.
std::string gltf_view_outside_its_buffer(const tinygltf::Model& model, const tinygltf::BufferView& view);

// A scalar accessor of unsigned bytes, shorts or ints, as vertex indices.
std::vector<uint32_t> read_gltf_indices(const tinygltf::Model& model, int accessor, const std::string& file,
                                        const std::string& use);

}  // namespace tracer
