// Image files through OpenImageIO. .exr, .hdr, .tif, .tiff and .pfm keep linear float32
// (EXR losslessly, zip-compressed); other formats (.png, .jpg, ...) get 8-bit sRGB,
// clamped to [0, 1]. Writes go through an OutputBatch (io/output_batch.h): a failed or
// interrupted write never leaves a partial image or clobbers the old one.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"
#include "io/output_batch.h"

namespace tracer {

// Images are 1 to kMaxImageSide pixels on a side (the film's limit) with 1 to
// kMaxImageChannels channels; a header asking for more is refused before any pixel is allocated.
constexpr int kMaxImageSide = 16384;
constexpr int kMaxImageChannels = 64;

// The pixels of an image file as float, the first `channels_read` of `channels`.
struct ImagePixels {
  uint32_t width = 0, height = 0;
  int channels = 0, channels_read = 0;
  bool float_format = false;  // stored as float or half (linear), not as 8/16-bit integers (sRGB)
  std::vector<float> values;  // width * height * channels_read, row by row
};

// The one reader of image files (compare, references, textures): a regular file, its header
// checked against the limits above (max_side at most kMaxImageSide), then the first
// min(channels, max_channels_read) channels. InputError naming the path when any of that
// fails, an allocation included.
ImagePixels read_image_pixels(const std::string& path, int max_channels_read, int max_side = kMaxImageSide);
// The same for an encoded image in memory, read by the reader of `format` ("png", "jpg");
// errors name `name`.
ImagePixels read_image_pixels_from_memory(const std::vector<unsigned char>& bytes, const std::string& format,
                                          const std::string& name, int max_channels_read);

// The bytes of the file `path` would hold: the format from its extension, as add_image writes it.
std::string encode_image(const Image& image, const std::string& path);
void add_image(OutputBatch& batch, const Image& image, const std::string& path);  // written on commit
void write_image(const Image& image, const std::string& path);                    // a batch of one
Image read_image(const std::string& path);  // RGB float; InputError when unreadable

// Fails (InputError naming the path and the option) when an image could not be written at
// path: no such directory, a directory, no extension, no writer for the extension. Commands
// call it before any work, so a bad output name never costs a render.
void check_image_output(const std::string& path, const std::string& option);
bool is_float_format(const std::string& path);

}  // namespace tracer
