#include "scene/gltf_reader_memory.h"

#include <tiny_gltf.h>

#include <nlohmann/json.hpp>

#include "io/input_error.h"

namespace tracer {
namespace {

// Each top-level array tinygltf keeps, with the struct it keeps an element in.
#define TRACER_GLTF_ARRAYS(X)            \
  X("accessors", tinygltf::Accessor)     \
  X("animations", tinygltf::Animation)   \
  X("buffers", tinygltf::Buffer)         \
  X("bufferViews", tinygltf::BufferView) \
  X("cameras", tinygltf::Camera)         \
  X("images", tinygltf::Image)           \
  X("materials", tinygltf::Material)     \
  X("meshes", tinygltf::Mesh)            \
  X("nodes", tinygltf::Node)             \
  X("samplers", tinygltf::Sampler)       \
  X("scenes", tinygltf::Scene)           \
  X("skins", tinygltf::Skin)             \
  X("textures", tinygltf::Texture)

constexpr uint64_t kGrowth = 3;  // a vector's elements, their spare capacity, the old block while it grows

uint64_t array_size(const Json& object, const char* key) {
  const auto it = object.find(key);
  return it != object.end() && it->is_array() ? it->size() : 0;
}

void add(GltfReaderBytes& b, const std::string& what, uint64_t count, uint64_t element_bytes) {
  const uint64_t bytes = count * element_bytes * kGrowth;  // counts < 2^32, structs < 2^12: no overflow
  b.total += bytes;
  if (bytes > b.largest_bytes) b.largest = what, b.largest_count = count, b.largest_bytes = bytes;
}

}  // namespace

GltfReaderBytes gltf_reader_bytes(const Json& root) {
  GltfReaderBytes b;
#define TRACER_GLTF_ARRAY_BYTES(key, Type) add(b, key, array_size(root, key), sizeof(Type));
  TRACER_GLTF_ARRAYS(TRACER_GLTF_ARRAY_BYTES)
#undef TRACER_GLTF_ARRAY_BYTES
  uint64_t primitives = 0, children = 0;
  if (const auto meshes = root.find("meshes"); meshes != root.end() && meshes->is_array())
    for (const Json& mesh : *meshes)
      if (mesh.is_object()) primitives += array_size(mesh, "primitives");
  if (const auto nodes = root.find("nodes"); nodes != root.end() && nodes->is_array())
    for (const Json& node : *nodes)
      if (node.is_object()) children += array_size(node, "children");
  add(b, "meshes[].primitives", primitives, sizeof(tinygltf::Primitive));
  add(b, "nodes[].children", children, sizeof(int));
  if (const auto buffers = root.find("buffers"); buffers != root.end() && buffers->is_array())
    for (const Json& buffer : *buffers)
      if (buffer.is_object() && buffer.contains("byteLength") && buffer["byteLength"].is_number_unsigned())
        b.total += buffer["byteLength"].get<uint64_t>();  // each below 2^53 (the schema)
  return b;
}

void check_gltf_reader_memory(const Json& root, const MemoryLimit& limit, const std::string& file) {
  const GltfReaderBytes b = gltf_reader_bytes(root);
  if (limit.bytes == 0 || b.total <= limit.bytes / 2) return;
  throw InputError(file + ": " + b.largest + ": " + std::to_string(b.largest_count) +
                   " elements; the glTF reader would hold up to " + std::to_string(b.total) +
                   " bytes for the file, more than half of " + limit.source + " (" + std::to_string(limit.bytes) +
                   " bytes)");
}

}  // namespace tracer
