#include "render/partial_file.h"

#include <cstring>

#include "io/input_error.h"
#include "io/out_of_memory.h"
#include "io/sha1.h"
#include "io/text_file.h"
#include "options/number_text.h"
#include "options/work_limits.h"

namespace tracer {
namespace {

constexpr const char* kMagic = "tracer-partial/2";
// A header line, then the largest film the limits allow: read_text_file refuses more unread.
constexpr uint64_t kMaxPartialBytes = (1u << 20) + uint64_t{kMaxResolution} * kMaxResolution * sizeof(FilmSum);
static_assert(sizeof(FilmSum) == 32, "the partial file stores film sums as 32 bytes");

std::string pixels_sha1(const FilmSum* pixels, size_t count) {
  Sha1 h;
  h.append(pixels, count * sizeof(FilmSum));
  return h.hex_digest();
}

}  // namespace

std::string encode_partial(const Partial& partial) {
  const PartialHeader& h = partial.header;
  const size_t count = partial.film.pixels.size();
  const Json header = {{"scene", h.scene},
                       {"scene_sha1", h.scene_sha1},
                       {"render", h.render},
                       {"spp", h.spp},
                       {"samples", {partial.film.range.begin, partial.film.range.end}},
                       {"width", partial.film.width},
                       {"height", partial.film.height},
                       {"nonfinite", h.nonfinite},
                       {"overflow", h.overflow},
                       {"pixels_sha1", pixels_sha1(partial.film.pixels.data(), count)}};
  std::string bytes = std::string(kMagic) + "\n" + header.dump() + "\n";
  const size_t start = bytes.size();
  bytes.resize(start + count * sizeof(FilmSum));
  std::memcpy(bytes.data() + start, partial.film.pixels.data(), count * sizeof(FilmSum));
  return bytes;
}

namespace {

Partial read_partial_unguarded(const std::string& path) {
  const std::string bytes = read_text_file(path, "partial file", kMaxPartialBytes);
  const size_t magic_end = bytes.find('\n');
  if (magic_end == std::string::npos || bytes.compare(0, magic_end, kMagic) != 0)
    throw InputError(path + ": not a partial file (expected the line \"" + std::string(kMagic) + "\")");
  const size_t header_end = bytes.find('\n', magic_end + 1);
  if (header_end == std::string::npos) throw InputError(path + ": truncated partial file (no header line)");
  const Json doc = parse_json_text(bytes.substr(magic_end + 1, header_end - magic_end - 1), path);
  JsonObject obj(doc, "", path);
  Partial p;
  p.header.scene = obj.string("scene");
  p.header.scene_sha1 = obj.string("scene_sha1");
  p.header.render = obj.get("render");
  p.header.spp = obj.unsigned_integer_32("spp");
  p.header.nonfinite = obj.unsigned_integer("nonfinite");
  p.header.overflow = obj.unsigned_integer("overflow");
  p.film.width = obj.unsigned_integer_32("width");
  p.film.height = obj.unsigned_integer_32("height");
  const std::string sha1 = obj.string("pixels_sha1");
  const Json& samples = obj.get("samples");
  if (!samples.is_array() || samples.size() != 2 || !samples[0].is_number_unsigned() ||
      !samples[1].is_number_unsigned() || samples[0].get<uint64_t>() > 0xffffffffu ||
      samples[1].get<uint64_t>() > 0xffffffffu)
    obj.fail("samples", "expected [begin, end], each fitting in 32 bits");
  p.film.range = {samples[0].get<uint32_t>(), samples[1].get<uint32_t>()};
  obj.finish();
  if (!(p.film.range.begin < p.film.range.end && p.film.range.end <= p.header.spp))
    obj.fail("samples", "expected 0 <= begin < end <= spp");
  // The render it is a part of is within the limits render applies (max_depth is in "render").
  if (const auto v = work_limit_violation(p.film.width, p.film.height, p.header.spp, 0)) obj.fail(v->key, v->reason);
  // The size is checked before anything is allocated for the pixels.
  const size_t count = static_cast<size_t>(p.film.width) * p.film.height;
  if (bytes.size() - header_end - 1 != count * sizeof(FilmSum))
    throw InputError(path + ": truncated or oversized partial file (expected " + std::to_string(count) + " pixels of " +
                     std::to_string(sizeof(FilmSum)) + " bytes after the header)");
  p.film.pixels.resize(count);
  std::memcpy(p.film.pixels.data(), bytes.data() + header_end + 1, count * sizeof(FilmSum));
  if (pixels_sha1(p.film.pixels.data(), count) != sha1)
    throw InputError(path + ": the film sums do not match pixels_sha1 (the file is damaged)");
  for (size_t i = 0; i < count; ++i)
    for (const int64_t v : p.film.pixels[i].rgb)
      if (v > kFilmSumLimit || v < -kFilmSumLimit)
        throw InputError(path + ": pixel " + std::to_string(i) +
                         " holds a film sum beyond 2^62 (not written by tracer)");
  return p;
}

}  // namespace

Partial read_partial(const std::string& path) {
  return naming_file_when_out_of_memory(path, "reading the partial file", [&] { return read_partial_unguarded(path); });
}

SampleRange parse_sample_range(const std::string& text, uint32_t spp) {
  const size_t colon = text.find(':');
  const auto bad = [&](const std::string& why) { return InputError("--samples " + text + ": " + why); };
  if (colon == std::string::npos) throw bad("expected A:B, the samples [A, B) of every pixel");
  const std::optional<uint64_t> a = parse_count(std::string_view(text).substr(0, colon), UINT32_MAX);
  const std::optional<uint64_t> b = parse_count(std::string_view(text).substr(colon + 1), UINT32_MAX);
  if (!a || !b) throw bad("expected A:B, each " + count_range(0, UINT32_MAX));
  if (!(*a < *b && *b <= spp)) throw bad("expected 0 <= A < B <= spp (" + std::to_string(spp) + ")");
  return {static_cast<uint32_t>(*a), static_cast<uint32_t>(*b)};
}

size_t add_film_sums(FilmBuffer& total, const FilmBuffer& part) {
  for (size_t i = 0; i < total.pixels.size(); ++i) {
    FilmSum& s = total.pixels[i];
    for (int c = 0; c < 3; ++c) {
      const int64_t sum = s.rgb[c] + part.pixels[i].rgb[c];  // each below 2^62 in magnitude: no int64 overflow
      if (sum > kFilmSumLimit || sum < -kFilmSumLimit) return i;
    }
    for (int c = 0; c < 3; ++c) s.rgb[c] += part.pixels[i].rgb[c];
    s.nonfinite += part.pixels[i].nonfinite;
    s.overflow += part.pixels[i].overflow;
  }
  return total.pixels.size();
}

}  // namespace tracer
