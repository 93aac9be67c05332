// Image files through OpenImageIO. .exr, .hdr, .tif, .tiff and .pfm keep linear float32
// (EXR losslessly, zip-compressed); other formats (.png, .jpg, ...) get 8-bit sRGB,
// clamped to [0, 1]. Writes go to a temporary file in the same directory, renamed into
// place, so an interrupted write never leaves a partial image or clobbers the old one.
#pragma once
#include <string>

#include "image/image.h"

namespace tracer {

void write_image(const Image& image, const std::string& path);
Image read_image(const std::string& path);  // RGB float; InputError when unreadable
bool is_float_format(const std::string& path);

}  // namespace tracer
