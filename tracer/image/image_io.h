// Image files through OpenImageIO. .exr, .hdr, .tif, .tiff and .pfm keep linear float32
// (EXR losslessly, zip-compressed); other formats (.png, .jpg, ...) get 8-bit sRGB,
// clamped to [0, 1]. Writes go through an OutputBatch (io/output_batch.h): a failed or
// interrupted write never leaves a partial image or clobbers the old one.
#pragma once
#include <string>

#include "image/image.h"
#include "io/output_batch.h"

namespace tracer {

void add_image(OutputBatch& batch, const Image& image, const std::string& path);  // written on commit
void write_image(const Image& image, const std::string& path);                    // a batch of one
Image read_image(const std::string& path);  // RGB float; InputError when unreadable

// Fails (InputError naming the path and the option) when an image could not be written at
// path: no such directory, a directory, no extension, no writer for the extension. Commands
// call it before any work, so a bad output name never costs a render.
void check_image_output(const std::string& path, const std::string& option);
bool is_float_format(const std::string& path);

}  // namespace tracer
