// An Image as an OpenImageIO ImageBuf (a copy), for OIIO's algorithms.
#pragma once
#include <OpenImageIO/imagebuf.h>

#include "image/image.h"

namespace tracer {

inline OIIO::ImageBuf to_image_buf(const Image& img) {
  OIIO::ImageSpec spec(static_cast<int>(img.width), static_cast<int>(img.height), 3, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf buf(spec);
  buf.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, img.rgb.data());
  return buf;
}

}  // namespace tracer
