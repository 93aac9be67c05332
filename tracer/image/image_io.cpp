#include "image/image_io.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "image/declared_size_check.h"
#include "io/input_error.h"
#include "io/output_paths.h"
#include "kernel/base/detmath.h"

namespace tracer {
namespace {

// sRGB transfer function (IEC 61966-2-1).
float linear_to_srgb(float x) {
  if (!(x > 0.0f)) return 0.0f;
  if (x >= 1.0f) return 1.0f;
  return x <= 0.0031308f ? 12.92f * x : 1.055f * det_pow(x, 1.0f / 2.4f) - 0.055f;
}

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

}  // namespace

bool is_float_format(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".exr" || ext == ".hdr" || ext == ".tif" || ext == ".tiff" || ext == ".pfm";
}

// OpenImageIO encodes into memory and our own writer puts the bytes on disk: its file writers
// report success when a write fails as the file is closed (OpenEXR on a full disk), which would
// rename an empty file over the old image.
std::string encode_image(const Image& image, const std::string& path) {
  if (std::filesystem::path(path).extension().empty())
    throw InputError(path + ": output needs a file extension (.exr, .png, ...)");
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw InputError(path + ": no image writer for this extension: " + OIIO::geterror());
  if (!out->supports("ioproxy"))
    throw InputError(path + ": this image format cannot be written safely; use .exr or .png");
  const bool linear = is_float_format(path);
  OIIO::ImageSpec spec(static_cast<int>(image.width), static_cast<int>(image.height), 3,
                       linear ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  if (lower_extension(path) == ".exr") spec.attribute("compression", "zip");
  OIIO::Filesystem::IOVecOutput memory;
  void* proxy = &memory;
  spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  bool ok = out->open(path, spec);
  if (ok && linear) {
    ok = out->write_image(OIIO::TypeDesc::FLOAT, image.rgb.data());
  } else if (ok) {
    std::vector<unsigned char> bytes(image.rgb.size());
    for (size_t i = 0; i < bytes.size(); ++i)
      bytes[i] = static_cast<unsigned char>(linear_to_srgb(image.rgb[i]) * 255.0f + 0.5f);
    ok = out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
  }
  ok = out->close() && ok;
  if (!ok) throw InputError(path + ": cannot encode image: " + out->geterror());
  const std::vector<unsigned char>& encoded = memory.buffer();
  return std::string(encoded.begin(), encoded.end());
}

void add_image(OutputBatch& batch, const Image& image, const std::string& path) {
  batch.add(path, encode_image(image, path));
}

void write_image(const Image& image, const std::string& path) {
  OutputBatch batch;
  add_image(batch, image, path);
  batch.commit();
}

void check_image_output(const std::string& path, const std::string& option) {
  check_output_location(path, option);
  const std::filesystem::path p(path);
  if (p.extension().empty())
    throw InputError(path + ": " + option + ": output needs a file extension (.exr, .png, ...)");
  if (!OIIO::ImageOutput::create(path))
    throw InputError(path + ": " + option + ": no image writer for extension " + p.extension().string());
}

// Opens `open_name` (through `proxy` when given: its extension picks the reader), checks the
// header against the limits and reads the pixels; errors name `path`.
ImagePixels read_opened_image(const std::string& open_name, const std::string& path, OIIO::Filesystem::IOProxy* proxy,
                              int max_channels_read, int max_side) {
  // Only the reader the extension names reads the file: by default OpenImageIO also tries
  // every other format library it links (DICOM, FITS, RAW, ...) on a file its own reader
  // refuses, which puts formats the tracer never documents in front of hostile input.
  static const bool one_reader = OIIO::attribute("try_all_readers", 0);
  (void)one_reader;
  // Colour and alpha as stored: a PNG's colour is not premultiplied by its alpha (glTF's base
  // colour and the tracer's alpha maps are straight alpha), which OpenImageIO does by default.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  if (proxy) config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);  // a config replaces the argument
  const std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(open_name, &config, proxy);
  if (!in) throw InputError(path + ": cannot read image: " + OIIO::geterror());
  // The header is input too: its size is checked before any pixel is allocated.
  const OIIO::ImageSpec& header = in->spec();
  max_side = std::min(max_side, kMaxImageSide);
  if (header.width < 1 || header.height < 1 || header.width > max_side || header.height > max_side || header.depth != 1)
    throw InputError(path + ": cannot read image: its header declares " + std::to_string(header.width) + "x" +
                     std::to_string(header.height) + " pixels; images are 1 to " + std::to_string(max_side) +
                     " pixels on a side" + (max_side == kMaxImageSide ? ", as the film" : ""));
  if (header.nchannels < 1 || header.nchannels > kMaxImageChannels)
    throw InputError(path + ": cannot read image: its header declares " + std::to_string(header.nchannels) +
                     " channels; images have 1 to " + std::to_string(kMaxImageChannels));
  ImagePixels image;
  image.width = static_cast<uint32_t>(header.width);
  image.height = static_cast<uint32_t>(header.height);
  image.channels = header.nchannels;
  image.channels_read = std::min(header.nchannels, max_channels_read);
  image.float_format = header.format.is_floating_point();
  const size_t count = size_t{image.width} * image.height * static_cast<size_t>(image.channels_read);
  try {
    image.values.resize(count);
  } catch (const std::bad_alloc&) {
    throw InputError(path + ": cannot read image: out of memory for its " + std::to_string(image.width) + "x" +
                     std::to_string(image.height) + "x" + std::to_string(image.channels_read) + " floats");
  }
  if (!in->read_image(0, 0, 0, image.channels_read, OIIO::TypeDesc::FLOAT, image.values.data()))
    throw InputError(path + ": cannot read image: " + in->geterror());
  return image;
}

ImagePixels read_image_pixels(const std::string& path, int max_channels_read, int max_side) {
  // A FIFO or a device would block OpenImageIO or never end.
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path + ": cannot read image: no such file");
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path + ": cannot read image: not a regular file");
  check_declared_sizes(path);
  return read_opened_image(path, path, nullptr, max_channels_read, max_side);
}

ImagePixels read_image_pixels_from_memory(const std::vector<unsigned char>& bytes, const std::string& format,
                                          const std::string& name, int max_channels_read) {
  check_declared_sizes(bytes, name);
  OIIO::Filesystem::IOMemReader proxy(bytes.data(), bytes.size());
  return read_opened_image("memory." + format, name, &proxy, max_channels_read, kMaxImageSide);
}

Image read_image(const std::string& path) {
  ImagePixels pixels = read_image_pixels(path, 3);
  if (pixels.channels < 3)
    throw InputError(path + ": cannot read image: expected 3 to " + std::to_string(kMaxImageChannels) +
                     " channels, got " + std::to_string(pixels.channels));
  Image image;
  image.width = pixels.width;
  image.height = pixels.height;
  image.rgb = std::move(pixels.values);
  return image;
}

}  // namespace tracer
