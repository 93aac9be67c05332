// `tracer merge PARTS... -o OUT`: adds the film sums of partial renders of one scene into the
// image of all its samples, identical bit for bit to rendering them at once.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "cli/command_registry.h"
#include "cli/commands.h"
#include "image/image_io.h"
#include "io/input_error.h"
#include "io/out_of_memory.h"
#include "io/output_paths.h"
#include "render/partial_file.h"

namespace tracer {

struct MergeCommand {
  std::vector<std::string> parts;
  std::string output;
};

static int run_merge(const MergeCommand& cmd) {
  check_image_output(cmd.output, "-o");
  refuse_outputs_naming_inputs({{cmd.output, "-o"}}, cmd.parts);
  std::vector<std::pair<std::string, Partial>> parts;
  for (const std::string& path : cmd.parts) parts.emplace_back(path, read_partial(path));

  const std::string& first_path = parts.front().first;
  const Partial& first = parts.front().second;
  for (const auto& [path, p] : parts) {
    const std::string& part_path = path;  // clang 14 cannot capture a structured binding in a lambda
    const auto differs = [&](const std::string& what) {
      return InputError(part_path + ": not a part of the same render as " + first_path + ": " + what + " differ");
    };
    if (p.header.scene_sha1 != first.header.scene_sha1) throw differs("the scene files' contents");
    if (p.header.render != first.header.render)
      throw differs("the render options (" + p.header.render.dump() + " against " + first.header.render.dump() + ")");
    if (p.header.spp != first.header.spp || p.film.width != first.film.width || p.film.height != first.film.height)
      throw differs("spp or image size");
  }
  std::sort(parts.begin(), parts.end(),
            [](const auto& a, const auto& b) { return a.second.film.range.begin < b.second.film.range.begin; });
  uint32_t next = 0;
  for (const auto& [path, p] : parts) {
    const SampleRange r = p.film.range;
    if (r.begin < next)
      throw InputError(path + ": samples [" + std::to_string(r.begin) + ", " + std::to_string(r.end) +
                       ") overlap samples another part already holds (up to " + std::to_string(next) + ")");
    if (r.begin > next)
      throw InputError(cmd.parts.front() + "...: no part holds samples [" + std::to_string(next) + ", " +
                       std::to_string(r.begin) + ")");
    next = r.end;
  }
  const uint32_t spp = first.header.spp;
  if (next != spp)
    throw InputError(cmd.parts.front() + "...: no part holds samples [" + std::to_string(next) + ", " +
                     std::to_string(spp) + ")");

  FilmBuffer total =
      naming_file_when_out_of_memory(cmd.output, "merging the parts", [&] { return parts.front().second.film; });
  total.range = {0, spp};
  uint64_t nonfinite = 0, overflow = 0;
  for (size_t k = 1; k < parts.size(); ++k) {
    const size_t overflowing = add_film_sums(total, parts[k].second.film);
    if (overflowing < total.pixels.size())
      throw InputError(parts[k].first + ": pixel " + std::to_string(overflowing) +
                       " overflows the film when the parts are added; render fewer, brighter-clamped samples");
  }
  for (const FilmSum& s : total.pixels) nonfinite += s.nonfinite, overflow += s.overflow;
  naming_file_when_out_of_memory(cmd.output, "writing the merged image",
                                 [&] { write_image(resolve_film(total, spp), cmd.output); });
  std::printf("merged %zu parts, samples [0, %u), %llu NaN/inf samples, %llu overflowing samples: wrote %s\n",
              parts.size(), spp, static_cast<unsigned long long>(nonfinite), static_cast<unsigned long long>(overflow),
              std::filesystem::absolute(cmd.output).string().c_str());
  return 0;
}

const RegisterCommand kMergeCommand(
    {"", "merge", "add partial renders (--samples) into the image of all their samples", [](CLI::App& app) {
       auto cmd = std::make_shared<MergeCommand>();
       app.add_option("parts", cmd->parts, "partial files of one render covering samples [0, spp) once")->required();
       app.add_option("-o,--output", cmd->output, "output image (.exr, .png, ...)")->required();
       return [cmd] { return run_merge(*cmd); };
     }});

}  // namespace tracer
