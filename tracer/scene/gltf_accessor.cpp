#include "scene/gltf_accessor.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "io/json_reader.h"

namespace tracer {
namespace {

// Bytes of one component, 0 for a type glTF does not allow.
uint64_t component_bytes(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

int type_components(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return 0;  // matrices are no vertex attribute the tracer reads
  }
}

// One component as a float; normalized integers map to [0, 1] or [-1, 1] (glTF 2.0, 3.11).
float component_value(const unsigned char* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const float c = static_cast<float>(static_cast<int8_t>(*p));
      return normalized ? std::max(c / 127.0f, -1.0f) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? *p / 255.0f : static_cast<float>(*p);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(static_cast<float>(v) / 32767.0f, -1.0f) : static_cast<float>(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? static_cast<float>(v) / 65535.0f : static_cast<float>(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return normalized ? static_cast<float>(static_cast<double>(v) / 4294967295.0) : static_cast<float>(v);
    }
    default: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

uint32_t index_value(const unsigned char* p, int type) {
  if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) return *p;
  if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
    uint16_t v;
    std::memcpy(&v, p, 2);
    return v;
  }
  uint32_t v;
  std::memcpy(&v, p, 4);
  return v;
}

}  // namespace

std::string gltf_view_outside_its_buffer(const tinygltf::Model& model, const tinygltf::BufferView& view) {
  const uint64_t buffer_bytes = model.buffers[static_cast<size_t>(view.buffer)].data.size();
  if (view.byteOffset <= buffer_bytes && view.byteLength <= buffer_bytes - view.byteOffset) return "";
  return "bytes [" + std::to_string(view.byteOffset) + ", +" + std::to_string(view.byteLength) +
         ") lie outside buffer " + std::to_string(view.buffer) + " of " + std::to_string(buffer_bytes) + " bytes";
}

namespace {

// `count` elements of `element_bytes` each, `stride` apart, from byte `offset` of a buffer
// view: the view must lie inside its buffer and the elements inside the view. Returns the
// first element's address.
const unsigned char* checked_elements(const tinygltf::Model& model, int view_index, uint64_t offset, uint64_t count,
                                      uint64_t element_bytes, uint64_t stride, const std::string& file,
                                      const std::string& path) {
  if (view_index < 0 || static_cast<size_t>(view_index) >= model.bufferViews.size())
    fail_at(file, path + ".bufferView",
            "names buffer view " + std::to_string(view_index) + "; the file has " +
                std::to_string(model.bufferViews.size()));
  const tinygltf::BufferView& view = model.bufferViews[view_index];
  const std::string view_path = "bufferViews[" + std::to_string(view_index) + "]";
  if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size())
    fail_at(file, view_path + ".buffer",
            "names buffer " + std::to_string(view.buffer) + "; the file has " + std::to_string(model.buffers.size()));
  const std::string outside = gltf_view_outside_its_buffer(model, view);
  if (!outside.empty()) fail_at(file, view_path + ".byteLength", outside);
  // Neither factor exceeds 2^32 here, so the product cannot overflow 64 bits.
  const uint64_t span = (count - 1) * stride + element_bytes;
  if (offset > view.byteLength || span > view.byteLength - offset)
    fail_at(file, path,
            std::to_string(count) + " elements of " + std::to_string(element_bytes) + " bytes, " +
                std::to_string(stride) + " apart from byte " + std::to_string(offset) + ", lie outside " + view_path +
                " of " + std::to_string(view.byteLength) + " bytes");
  return model.buffers[view.buffer].data.data() + view.byteOffset + offset;
}

struct CheckedAccessor {
  const tinygltf::Accessor* accessor;
  std::string path;
  int components;
  uint64_t component_size;
};

CheckedAccessor check_accessor(const tinygltf::Model& model, int index, const std::string& file,
                               const std::string& use) {
  if (index < 0 || static_cast<size_t>(index) >= model.accessors.size())
    fail_at(file, use,
            "names accessor " + std::to_string(index) + "; the file has " + std::to_string(model.accessors.size()));
  const tinygltf::Accessor& a = model.accessors[index];
  CheckedAccessor c{&a, "accessors[" + std::to_string(index) + "]", type_components(a.type),
                    component_bytes(a.componentType)};
  if (c.component_size == 0)
    fail_at(file, c.path + ".componentType", "is " + std::to_string(a.componentType) + ", not a glTF component type");
  if (c.components == 0) fail_at(file, c.path + ".type", "is not SCALAR or VEC2-4 (referred to by " + use + ")");
  if (a.count < 1 || a.count > kMaxGltfAccessorCount)
    fail_at(file, c.path + ".count",
            "is " + std::to_string(a.count) + "; accessors hold 1 to 2^26 elements (referred to by " + use + ")");
  return c;
}

// Every element's components as raw bytes' addresses: `at(i)` is element i.
struct ElementSource {
  const unsigned char* base = nullptr;
  uint64_t stride = 0;
  const unsigned char* at(uint64_t i) const { return base + i * stride; }
};

ElementSource element_source(const tinygltf::Model& model, const CheckedAccessor& c, const std::string& file) {
  const tinygltf::Accessor& a = *c.accessor;
  const uint64_t element = c.component_size * static_cast<uint64_t>(c.components);
  if (a.bufferView < 0) return {};  // no buffer view: every element is zero (before sparse substitution)
  const tinygltf::BufferView* view =
      static_cast<size_t>(a.bufferView) < model.bufferViews.size() ? &model.bufferViews[a.bufferView] : nullptr;
  const uint64_t stride = view && view->byteStride ? view->byteStride : element;
  if (stride < element || stride > 252)
    fail_at(file, "bufferViews[" + std::to_string(a.bufferView) + "].byteStride",
            "is " + std::to_string(stride) + "; it must hold one element of " + c.path + " (" +
                std::to_string(element) + " bytes) and be at most 252");
  if (a.byteOffset % c.component_size != 0)
    fail_at(file, c.path + ".byteOffset", "is not a multiple of the component size");
  return {checked_elements(model, a.bufferView, a.byteOffset, a.count, element, stride, file, c.path), stride};
}

// Applies the accessor's sparse substitution (glTF 2.0, 3.6.2.3) through `store(i, element)`.
template <class Store>
void apply_sparse(const tinygltf::Model& model, const CheckedAccessor& c, const std::string& file, Store store) {
  const tinygltf::Accessor& a = *c.accessor;
  if (!a.sparse.isSparse) return;
  const std::string path = c.path + ".sparse";
  if (a.sparse.count < 1 || static_cast<uint64_t>(a.sparse.count) > a.count)
    fail_at(file, path + ".count", "is " + std::to_string(a.sparse.count) + "; expected 1 to the accessor's count");
  const int index_type = a.sparse.indices.componentType;
  if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    fail_at(file, path + ".indices.componentType", "must be an unsigned byte, short or int");
  if (a.sparse.indices.byteOffset < 0 || a.sparse.values.byteOffset < 0)
    fail_at(file, path, "a byteOffset is negative");
  const uint64_t count = static_cast<uint64_t>(a.sparse.count), index_bytes = component_bytes(index_type);
  const uint64_t element = c.component_size * static_cast<uint64_t>(c.components);
  const unsigned char* indices = checked_elements(model, a.sparse.indices.bufferView, a.sparse.indices.byteOffset,
                                                  count, index_bytes, index_bytes, file, path + ".indices");
  const unsigned char* values = checked_elements(model, a.sparse.values.bufferView, a.sparse.values.byteOffset, count,
                                                 element, element, file, path + ".values");
  for (uint64_t i = 0; i < count; ++i) {
    const uint32_t target = index_value(indices + i * index_bytes, index_type);
    if (target >= a.count)
      fail_at(file, path + ".indices",
              "index " + std::to_string(target) + " is beyond the accessor's " + std::to_string(a.count) + " elements");
    store(target, values + i * element);
  }
}

}  // namespace

std::vector<float> read_gltf_floats(const tinygltf::Model& model, int accessor, int components, const std::string& file,
                                    const std::string& use) {
  const CheckedAccessor c = check_accessor(model, accessor, file, use);
  if (c.components != components)
    fail_at(file, c.path + ".type",
            "has " + std::to_string(c.components) + " components; " + use + " needs " + std::to_string(components));
  const tinygltf::Accessor& a = *c.accessor;
  const ElementSource src = element_source(model, c, file);
  std::vector<float> out(a.count * static_cast<uint64_t>(components), 0.0f);
  const auto store = [&](uint64_t i, const unsigned char* p) {
    for (int k = 0; k < components; ++k)
      out[i * components + k] = component_value(p + k * c.component_size, a.componentType, a.normalized);
  };
  if (src.base)
    for (uint64_t i = 0; i < a.count; ++i) store(i, src.at(i));
  apply_sparse(model, c, file, store);
  for (size_t i = 0; i < out.size(); ++i)
    if (!std::isfinite(out[i]))
      fail_at(file, c.path,
              "element " + std::to_string(i / components) + " is not finite (referred to by " + use + ")");
  return out;
}

std::vector<uint32_t> read_gltf_indices(const tinygltf::Model& model, int accessor, const std::string& file,
                                        const std::string& use) {
  const CheckedAccessor c = check_accessor(model, accessor, file, use);
  const tinygltf::Accessor& a = *c.accessor;
  if (c.components != 1 || a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
      a.componentType == TINYGLTF_COMPONENT_TYPE_BYTE || a.componentType == TINYGLTF_COMPONENT_TYPE_SHORT)
    fail_at(file, c.path, "indices must be SCALAR unsigned bytes, shorts or ints (referred to by " + use + ")");
  const ElementSource src = element_source(model, c, file);
  std::vector<uint32_t> out(a.count, 0);
  const auto store = [&](uint64_t i, const unsigned char* p) { out[i] = index_value(p, a.componentType); };
  if (src.base)
    for (uint64_t i = 0; i < a.count; ++i) store(i, src.at(i));
  apply_sparse(model, c, file, store);
  return out;
}

}  // namespace tracer
