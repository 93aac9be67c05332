#include "render/effects.h"

#include <sstream>

#include "io/input_error.h"
#include "kernel/scene/scene_view.h"

namespace tracer {
namespace {

struct EffectName {
  const char* name;
  uint32_t bit;
};
constexpr EffectName kEffects[] = {{"shadows", kEffectShadows}, {"reflections", kEffectReflection}, {"refractions", kEffectRefraction}};

}  // namespace

uint32_t parse_effects(const std::string& list) {
  if (list == "all") return kEffectAll;
  if (list == "none") return 0;
  uint32_t mask = 0;
  std::stringstream items(list);
  std::string item;
  while (std::getline(items, item, ',')) {
    bool known = false;
    for (const EffectName& e : kEffects)
      if (item == e.name) mask |= e.bit, known = true;
    if (!known)
      throw InputError("--effects " + list + ": unknown effect \"" + item +
                       "\" (expected a comma-separated list of shadows, reflections, refractions, or all, or none)");
  }
  return mask;
}

std::string effects_name(uint32_t mask) {
  if (mask == kEffectAll) return "all";
  std::string out = "shading";
  for (const EffectName& e : kEffects)
    if (mask & e.bit) out += std::string(" + ") + e.name;
  return out == "shading" ? "shading only" : out;
}

}  // namespace tracer
