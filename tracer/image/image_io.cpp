#include "image/image_io.h"

#include <unistd.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "io/input_error.h"
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

void write_image(const Image& image, const std::string& path) {
  const std::filesystem::path target(path);
  if (target.extension().empty()) throw InputError(path + ": output needs a file extension (.exr, .png, ...)");
  const std::filesystem::path temp = target.parent_path() / ("." + target.stem().string() + ".tmp" +
                                                             std::to_string(getpid()) + target.extension().string());
  auto out = OIIO::ImageOutput::create(temp.string());
  if (!out) throw InputError(path + ": no image writer for this extension: " + OIIO::geterror());
  const bool linear = is_float_format(path);
  OIIO::ImageSpec spec(static_cast<int>(image.width), static_cast<int>(image.height), 3,
                       linear ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  if (lower_extension(path) == ".exr") spec.attribute("compression", "zip");
  bool ok = out->open(temp.string(), spec);
  if (ok && linear) {
    ok = out->write_image(OIIO::TypeDesc::FLOAT, image.rgb.data());
  } else if (ok) {
    std::vector<unsigned char> bytes(image.rgb.size());
    for (size_t i = 0; i < bytes.size(); ++i)
      bytes[i] = static_cast<unsigned char>(linear_to_srgb(image.rgb[i]) * 255.0f + 0.5f);
    ok = out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
  }
  const std::string error = out->geterror();
  ok = out->close() && ok;
  std::error_code ec;
  if (ok) std::filesystem::rename(temp, target, ec);
  if (!ok || ec) {
    std::filesystem::remove(temp, ec);
    throw InputError(path + ": cannot write image: " +
                     (!error.empty() ? error
                      : ec           ? ec.message()
                                     : "the image writer failed (is the disk full?)"));
  }
}

Image read_image(const std::string& path) {
  // A FIFO or a device would block OpenImageIO or never end.
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path + ": cannot read image: no such file");
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path + ": cannot read image: not a regular file");
  OIIO::ImageBuf buf(path);
  if (!buf.read(0, 0, true, OIIO::TypeDesc::FLOAT)) throw InputError(path + ": cannot read image: " + buf.geterror());
  const OIIO::ImageSpec& spec = buf.spec();
  if (spec.nchannels < 3)
    throw InputError(path + ": expected at least 3 channels, got " + std::to_string(spec.nchannels));
  Image image;
  image.width = static_cast<uint32_t>(spec.width);
  image.height = static_cast<uint32_t>(spec.height);
  image.rgb.resize(static_cast<size_t>(spec.width) * spec.height * 3);
  buf.get_pixels(OIIO::ROI(spec.x, spec.x + spec.width, spec.y, spec.y + spec.height, 0, 1, 0, 3),
                 OIIO::TypeDesc::FLOAT, image.rgb.data());
  return image;
}

}  // namespace tracer
