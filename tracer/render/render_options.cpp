#include "render/render_options.h"

#include "scene/scene_types.h"

namespace tracer {

bool RenderOptions::complete() const {
  return integrator && sampler && accel && spp && width && height && max_depth && seed;
}

RenderOverrides RenderOptions::overrides() const {
  RenderOverrides o;
  o.integrator = integrator;
  o.sampler = sampler;
  o.accel = accel;
  o.spp = spp;
  o.width = width;
  o.height = height;
  o.max_depth = max_depth;
  o.seed = seed;
  o.nee = nee;
  o.rr_depth = rr_depth;
  o.sky_sampling = sky_sampling;
  o.triangle_test = triangle_test;
  return o;
}

nlohmann::ordered_json RenderOptions::to_json() const {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  if (integrator) j["integrator"] = *integrator;
  if (sampler) j["sampler"] = *sampler;
  if (spp) j["spp"] = *spp;
  if (seed) j["seed"] = *seed;
  if (width) j["width"] = *width;
  if (height) j["height"] = *height;
  if (accel) j["accel"] = *accel;
  if (max_depth) j["max_depth"] = *max_depth;
  if (nee) j["nee"] = *nee;
  if (rr_depth) j["rr_depth"] = *rr_depth;
  if (sky_sampling) j["sky_sampling"] = *sky_sampling;
  if (triangle_test) j["triangle_test"] = *triangle_test;
  return j;
}

RenderOptions resolved_options(const Scene& scene) {
  const RenderSettings& rs = scene.settings;
  const auto& names = accepted_scene_types();
  RenderOptions o;
  o.integrator = names.at("integrator").at(static_cast<size_t>(rs.integrator));
  o.sampler = names.at("sampler").at(static_cast<size_t>(rs.sampler));
  o.accel = names.at("accel").at(static_cast<size_t>(rs.accel));
  o.spp = rs.spp;
  o.width = rs.width;
  o.height = rs.height;
  o.max_depth = rs.max_depth;
  o.seed = rs.seed;
  if (rs.triangle_test == TriangleTest::MollerTrumbore) o.triangle_test = "moller-trumbore";
  if (rs.integrator == IntegratorKind::Path) {
    o.nee = rs.nee != 0;
    o.rr_depth = rs.rr_depth;
    if (scene.background.kind == BackgroundKind::Cubemap) o.sky_sampling = rs.sky_sampling != 0;
  }
  return o;
}

}  // namespace tracer
