// What the reader changes in a glTF file's JSON before tinygltf reads it, so that every file
// the specification allows loads, and the parts the tracer does not read are not judged:
// - a data URI of any media type, base64 or percent-encoded (RFC 2397), becomes the base64
//   form tinygltf decodes (it takes any other for a file name);
// - a buffer no buffer view uses is dropped (the buffer views renumbered), so an unused
//   buffer without `uri` is not read as the folder or as a .glb's binary chunk; a used one
//   without `uri` other than a .glb's first is refused by its JSON path;
// - an accessor no mesh primitive reads (skins', animations', morph targets') becomes an
//   empty SCALAR one, so a type or layout the tracer never reads cannot refuse the file;
// - an index accessor without a buffer view (zeros, before any sparse substitution) is given
//   a view of 4 zero bytes, which tinygltf insists on; the returned accessors are to have it
//   taken away once tinygltf has read the file.
// - every "extras" and the animations are dropped (the tracer reads neither), and the
//   materials no mesh primitive names (the others renumbered; their indices in the file are
//   returned, for messages): tinygltf keeps each element in hundreds of bytes to kilobytes.
// Errors are InputErrors naming the file and the JSON path.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "io/json_reader.h"

namespace tracer {

struct NormalizedGltf {
  std::vector<int> viewless_index_accessors;  // to have their buffer view taken away after loading
  std::vector<uint64_t> material_in_file;     // per material kept: its index in the file
  uint64_t materials_in_file = 0;             // the file's own count
};

NormalizedGltf normalize_gltf_json(Json& root, bool binary, const std::string& file);

// The .glb `bytes` with its JSON chunk replaced by `json` (glTF 2.0, 4.4: padded with spaces
// to 4 bytes, the header's length updated); the chunks after it are kept as they were.
std::string glb_with_json(const std::string& bytes, const std::string& json, const std::string& file);

}  // namespace tracer
