#include "render/partial_file.h"

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "io/input_error.h"

namespace tracer {
namespace {

constexpr const char* kMagic = "tracer-partial/1";
static_assert(sizeof(FilmSum) == 32, "the partial file stores film sums as 32 bytes");

}  // namespace

void write_partial(const std::string& path, const Partial& partial) {
  const PartialHeader& h = partial.header;
  Json header = {{"scene", h.scene},
                 {"scene_sha1", h.scene_sha1},
                 {"render", h.render},
                 {"spp", h.spp},
                 {"samples", {partial.film.range.begin, partial.film.range.end}},
                 {"width", partial.film.width},
                 {"height", partial.film.height},
                 {"nonfinite", h.nonfinite},
                 {"overflow", h.overflow}};
  const std::filesystem::path target(path);
  const std::filesystem::path temp =
      target.parent_path() / ("." + target.filename().string() + ".tmp" + std::to_string(getpid()));
  {
    std::ofstream out(temp, std::ios::binary);
    out << kMagic << "\n" << header.dump() << "\n";
    out.write(reinterpret_cast<const char*>(partial.film.pixels.data()),
              static_cast<std::streamsize>(partial.film.pixels.size() * sizeof(FilmSum)));
    if (!out) {
      std::error_code ec;
      std::filesystem::remove(temp, ec);
      throw InputError(path + ": cannot write the partial file");
    }
  }
  std::filesystem::rename(temp, target);
}

Partial read_partial(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the partial file");
  std::string magic, line;
  std::getline(in, magic);
  if (magic != kMagic)
    throw InputError(path + ": not a partial file (expected the line \"" + std::string(kMagic) + "\")");
  std::getline(in, line);
  const Json doc = parse_json_text(line, path);
  JsonObject obj(doc, "", path);
  Partial p;
  p.header.scene = obj.string("scene");
  p.header.scene_sha1 = obj.string("scene_sha1");
  p.header.render = obj.get("render");
  p.header.spp = static_cast<uint32_t>(obj.unsigned_integer("spp"));
  p.header.nonfinite = obj.unsigned_integer("nonfinite");
  p.header.overflow = obj.unsigned_integer("overflow");
  p.film.width = static_cast<uint32_t>(obj.unsigned_integer("width"));
  p.film.height = static_cast<uint32_t>(obj.unsigned_integer("height"));
  const Json& samples = obj.get("samples");
  if (!samples.is_array() || samples.size() != 2 || !samples[0].is_number_unsigned() ||
      !samples[1].is_number_unsigned())
    obj.fail("samples", "expected [begin, end]");
  p.film.range = {samples[0].get<uint32_t>(), samples[1].get<uint32_t>()};
  obj.finish();
  if (!(p.film.range.begin < p.film.range.end && p.film.range.end <= p.header.spp))
    obj.fail("samples", "expected 0 <= begin < end <= spp");
  const size_t count = static_cast<size_t>(p.film.width) * p.film.height;
  p.film.pixels.resize(count);
  in.read(reinterpret_cast<char*>(p.film.pixels.data()), static_cast<std::streamsize>(count * sizeof(FilmSum)));
  if (static_cast<size_t>(in.gcount()) != count * sizeof(FilmSum) || in.peek() != std::char_traits<char>::eof())
    throw InputError(path + ": truncated or oversized partial file (expected " + std::to_string(count) + " pixels)");
  return p;
}

SampleRange parse_sample_range(const std::string& text, uint32_t spp) {
  const size_t colon = text.find(':');
  const auto bad = [&](const std::string& why) { return InputError("--samples " + text + ": " + why); };
  if (colon == std::string::npos) throw bad("expected A:B, the samples [A, B) of every pixel");
  uint64_t a = 0, b = 0;
  try {
    size_t used_a = 0, used_b = 0;
    a = std::stoull(text.substr(0, colon), &used_a);
    b = std::stoull(text.substr(colon + 1), &used_b);
    if (used_a != colon || used_b != text.size() - colon - 1 || text[0] == '-' || text[colon + 1] == '-')
      throw std::invalid_argument("");
  } catch (const std::exception&) {
    throw bad("expected A:B with non-negative integers");
  }
  if (!(a < b && b <= spp)) throw bad("expected 0 <= A < B <= spp (" + std::to_string(spp) + ")");
  return {static_cast<uint32_t>(a), static_cast<uint32_t>(b)};
}

}  // namespace tracer
