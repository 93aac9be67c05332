// OpenEXR's reader allocates each header attribute's declared size before it reads the value:
// a 644-byte file declaring a 1.8 GB string attribute made every command that reads images
// allocate 1.8 GB (found by fuzz.image). Before OpenImageIO opens an EXR, every attribute of
// every header (OpenEXR file layout: magic, version, then per header "name\0 type\0 size
// value" up to an empty name; multi-part files end with an empty header) must fit in the file.
#pragma once
#include <string>

namespace tracer {

// InputError "PATH: cannot read image: ..." when the file starts as an EXR and one of its
// headers is cut short or declares an attribute larger than what is left of the file.
// Files that do not start with the EXR magic number are left to their readers.
void check_exr_header_sizes(const std::string& path);

}  // namespace tracer
