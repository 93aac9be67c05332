// A strict pass over an OBJ file's text before tinyobjloader parses it: tinyobjloader reads
// "nan", words and missing coordinates as 0, accepts face indices beyond 32 bits and drops
// two-vertex faces. Checked here: `v` has 3 (or 4, or 6 with colours) finite numbers, `vn`
// 3, `vt` 2 or 3; `f` has at least 3 references, each i, i/j, i//k or i/j/k with non-zero
// integers that fit in 32 bits. Other statements are tinyobjloader's to read.
#pragma once
#include <string>

namespace tracer {

// InputError "WHERE: LINE: message" for the first bad statement.
void check_obj_text(const std::string& text, const std::string& where);

}  // namespace tracer
