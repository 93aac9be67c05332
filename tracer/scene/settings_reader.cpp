#include "scene/settings_reader.h"

#include <nlohmann/json.hpp>

#include "kernel/integrator/ray_counts.h"
#include "options/enum_names.h"
#include "options/settings_check.h"

namespace tracer {

RenderSettings read_settings(const Json* render, const Json& film, const std::string& file,
                             const RenderOverrides& overrides, std::set<std::string>& used_types) {
  const Json empty = Json::object();
  RenderOptions from_file;
  JsonObject render_obj(render ? *render : empty, "render", file);
  read_options(render_obj, "render", from_file);
  render_obj.finish();
  JsonObject film_obj(film, "film", file);
  read_options(film_obj, "film", from_file);
  film_obj.finish();

  RenderSettings rs{};
  from_file.apply_to(rs);
  overrides.apply_to(rs);
  // Where an option's value came from, for the messages below.
  const auto where = [&](const std::string& name) {
    if (overrides.has(name))
      return overrides.origin.empty() ? file + ": command line " + option_flag(name)
                                      : overrides.origin + "." + name + " (the options of " + file + ")";
    for (const OptionInfo& o : option_table())
      if (name == o.name) return file + ": " + o.section + "." + name;
    return file + ": " + name;
  };

  used_types.insert(std::string("sampler:") + enum_name(rs.sampler));
  used_types.insert(std::string("integrator:") + enum_name(rs.integrator));
  used_types.insert(std::string("accel:") + enum_name(rs.accel));
  if (rs.grid_resolution > 1024)
    throw InputError(where("grid_resolution") + ": must be at most 1024 cells along the longest axis");
  if (const auto v = work_limit_violation(rs.width, rs.height, rs.spp, rs.max_depth))
    throw InputError(where(v->key) + ": " + v->reason);
  rs.grid_n = 1;
  while (static_cast<uint64_t>(rs.grid_n) * rs.grid_n < rs.spp) ++rs.grid_n;
  const bool square = static_cast<uint64_t>(rs.grid_n) * rs.grid_n == rs.spp;
  if (rs.sampler == SamplerKind::Center && rs.spp != 1)
    throw InputError(where("sampler") + ": the center sampler takes exactly 1 spp, got " + std::to_string(rs.spp));
  if ((rs.sampler == SamplerKind::Grid || rs.sampler == SamplerKind::Stratified) && !square)
    throw InputError(where("spp") + ": the " + enum_name(rs.sampler) +
                     " sampler needs a square spp (1, 4, 9, 16, ...), got " + std::to_string(rs.spp));
  if (overrides.has("stream_width") || from_file.has("stream_width")) {
    if (rs.schedule != Schedule::Stream)
      throw InputError(where("stream_width") + ": stream_width is the stream schedule's; it needs schedule stream");
    if (rs.stream_width < 1 || rs.stream_width > kMaxStreamWidth)
      throw InputError(where("stream_width") + ": expected 1 to " + std::to_string(kMaxStreamWidth) +
                       " samples in flight, got " + std::to_string(rs.stream_width));
  }
  if ((overrides.has("stream_order") || from_file.has("stream_order")) && rs.schedule != Schedule::Stream)
    throw InputError(where("stream_order") + ": stream_order is the stream schedule's; it needs schedule stream");
  const bool adaptive = rs.noise_threshold > 0.0f || rs.target_error > 0.0f;
  if (!adaptive && (overrides.has("min_spp") || from_file.has("min_spp")))
    throw InputError(where("min_spp") +
                     ": min_spp is adaptive sampling's minimum; it needs noise_threshold or "
                     "target_error");
  if (adaptive) {  // adaptive sampling (docs/path.md)
    // The key to blame: the sampler where the command gave it, else the adaptive key set.
    const char* key = overrides.has("sampler")    ? "sampler"
                      : rs.noise_threshold > 0.0f ? "noise_threshold"
                                                  : "target_error";
    if (rs.sampler == SamplerKind::Center || rs.sampler == SamplerKind::Grid || rs.sampler == SamplerKind::Stratified)
      throw InputError(where(key) +
                       ": adaptive sampling needs a sampler whose every prefix of samples "
                       "covers the whole pixel (stochastic or sobol), not " +
                       enum_name(rs.sampler));
    if (overrides.has("min_spp") || from_file.has("min_spp")) {
      if (rs.min_spp > rs.spp)
        throw InputError(where("min_spp") + ": " + std::to_string(rs.min_spp) + " is above spp " +
                         std::to_string(rs.spp) + ", the most samples a pixel takes");
    }
  }
  // What every render's settings hold, the check a bundle's reader makes too.
  if (const auto v = settings_violation(rs)) throw InputError(where(v->key) + ": " + v->reason);
  return rs;
}

}  // namespace tracer
