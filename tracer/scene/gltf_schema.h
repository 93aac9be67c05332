// The JSON types of a glTF file's properties (glTF 2.0's schema, the parts the tracer reads
// or that name other objects), checked on the parsed document before tinygltf reads it:
// tinygltf skips a property of the wrong type silently ("name": 42, "scale": "x", a
// `primitives` that is an object), which would render a broken file as if it were whole.
// Also refuses a file whose extensionsRequired names an extension the tracer does not read.
// Errors are InputErrors naming the file and the JSON path.
#pragma once
#include <string>

#include "io/json_reader.h"

namespace tracer {

void check_gltf_schema(const Json& root, const std::string& file);

}  // namespace tracer
