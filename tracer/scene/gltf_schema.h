// The JSON types of a glTF file's properties (glTF 2.0's schema, the parts the tracer reads
// or that name other objects), checked on the parsed document before tinygltf reads it:
// tinygltf skips a property of the wrong type silently ("name": 42, "scale": "x", a
// `primitives` that is an object), which would render a broken file as if it were whole.
// A property glTF requires that is missing is refused here, in the project's words; a whole
// number written as a float (12.0) is rewritten as an integer, which tinygltf insists on.
// Also refuses a file whose extensionsRequired names an extension the tracer does not read.
// Errors are InputErrors naming the file and the JSON path.
#pragma once
#include <string>

#include "io/json_reader.h"

namespace tracer {

void check_gltf_schema(Json& root, const std::string& file);

// Whether the reader reads the extension `name` (docs/gltf.md's table).
bool gltf_extension_read(const std::string& name);

}  // namespace tracer
