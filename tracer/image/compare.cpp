#include "image/compare.h"

#include <OpenImageIO/imagebufalgo.h>
#include <cstring>
#include <sstream>

#include "image/image_buf.h"

namespace tracer {

CompareResult compare_images(const Image& a, const Image& b, const CompareOptions& options) {
  CompareResult r;
  r.pixels = static_cast<uint64_t>(a.width) * a.height;
  if (a.width != b.width || a.height != b.height) {
    r.same_size = false;
    r.verdict = Verdict::Fail;
    return r;
  }
  for (size_t i = 0; i < a.rgb.size(); i += 3)
    r.pixels_not_identical += std::memcmp(&a.rgb[i], &b.rgb[i], 3 * sizeof(float)) != 0;
  r.bit_identical = r.pixels_not_identical == 0;
  const OIIO::ImageBuf ba = to_image_buf(a), bb = to_image_buf(b);
  const auto cr = OIIO::ImageBufAlgo::compare(ba, bb, options.fail, options.warn);
  r.mean_error = cr.meanerror;
  r.rms_error = cr.rms_error;
  r.psnr = cr.PSNR;
  r.max_error = cr.maxerror;
  r.max_x = cr.maxx;
  r.max_y = cr.maxy;
  r.pixels_over_warn = cr.nwarn;
  r.pixels_over_fail = cr.nfail;
  const double allowed_fail = options.failpercent / 100.0 * static_cast<double>(r.pixels);
  const double allowed_warn = options.warnpercent / 100.0 * static_cast<double>(r.pixels);
  if (options.fail == 0.0f ? !r.bit_identical : static_cast<double>(cr.nfail) > allowed_fail || cr.error)
    r.verdict = Verdict::Fail;
  else if (static_cast<double>(cr.nwarn) > allowed_warn)
    r.verdict = Verdict::Warn;
  else
    r.verdict = Verdict::Pass;
  return r;
}

Image difference_image(const Image& a, const Image& b) {
  Image d = a;
  for (size_t i = 0; i < d.rgb.size(); ++i) d.rgb[i] = std::abs(a.rgb[i] - b.rgb[i]);
  return d;
}

std::string describe(const CompareResult& r) {
  std::ostringstream s;
  if (!r.same_size) return "images differ in size";
  if (r.bit_identical) {
    s << "bit-identical, " << r.pixels << " pixels";
    return s.str();
  }
  s << r.pixels_not_identical << " of " << r.pixels << " pixels not bit-identical, " << r.pixels_over_fail
    << " over the fail threshold, " << r.pixels_over_warn << " over warn; max error " << r.max_error << " at ("
    << r.max_x << ", " << r.max_y << "), mean " << r.mean_error << ", RMS " << r.rms_error << ", PSNR " << r.psnr
    << " dB";
  return s.str();
}

}  // namespace tracer
