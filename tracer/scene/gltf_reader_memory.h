// What tinygltf will hold of a glTF file, bounded before it reads one: tinygltf keeps every
// element of the top-level arrays (and each mesh's primitives) in a struct of a few hundred
// bytes to 2 KB, however little the file writes for it ({} is a node), so a file of bare
// elements takes 20-50 times its size (docs/gltf.md). The bound counts each element at its
// struct's size three times over (a vector grown by doubling holds at most twice its elements
// and, while it grows, the old block beside the new) and the buffers' bytes once; a file whose
// bound passes half of the memory this process may use (io/memory_limit.h) is refused, naming
// the array that costs most, since Linux would lend the memory and kill the process later.
#pragma once
#include <cstdint>
#include <string>

#include "io/json_reader.h"
#include "io/memory_limit.h"

namespace tracer {

struct GltfReaderBytes {
  uint64_t total = 0;
  std::string largest;  // the JSON path of the array that costs most ("nodes", "meshes[].primitives")
  uint64_t largest_count = 0, largest_bytes = 0;
};

// The bound, from the parsed, schema-checked document (its buffers' byteLength included).
GltfReaderBytes gltf_reader_bytes(const Json& root);

// Throws an InputError naming `file` and the costliest array when the bound passes half of `limit`.
void check_gltf_reader_memory(const Json& root, const MemoryLimit& limit, const std::string& file);

}  // namespace tracer
