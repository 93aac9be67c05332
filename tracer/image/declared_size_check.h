// Image libraries allocate what a file's header declares before they read it: OpenEXR each
// header attribute's size (a 644-byte file declared a 1.8 GB string), libpng each chunk's
// length (a 342-byte PNG declared a 2 GB text chunk). Both found by fuzz.image. Before
// OpenImageIO opens an EXR or a PNG, every size its header declares must fit in the file,
// and the pixels a PNG or a JPEG declares must fit in its compressed data (deflate's 1032:1;
// a JPEG's bit per 8x8 block), which must end as its format ends (a JPEG's EOI marker).
//   EXR (OpenEXR file layout): magic, version, then per header "name\0 type\0 size value"
//   up to an empty name; multi-part files end with an empty header.
//   PNG (ISO/IEC 15948): signature, then chunks "length type data crc" up to IEND.
//   JPEG (ITU T.81): SOI, then marker segments "FF type length data" up to the first scan.
#pragma once
#include <string>
#include <vector>

namespace tracer {

// InputError "PATH: cannot read image: its EXR header ..." or "... its PNG chunk ..." when a
// declared size is larger than what is left of the file or the structure is cut short
// ("... its JPEG data ..." likewise).
// Files of other formats are left to their readers.
void check_declared_sizes(const std::string& path);
void check_declared_sizes(const std::vector<unsigned char>& bytes, const std::string& name);  // an image in memory

}  // namespace tracer
