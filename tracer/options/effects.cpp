#include "options/effects.h"

#include <sstream>

#include "io/input_error.h"

namespace tracer {
namespace {

struct EffectName {
  const char* name;
  Effects bit;
};
constexpr EffectName kEffects[] = {
    {"shadows", kEffectShadows}, {"reflections", kEffectReflection}, {"refractions", kEffectRefraction}};

}  // namespace

Effects parse_effects(const std::string& list, const std::string& where) {
  if (list == "all") return kEffectAll;
  if (list == "none") return kEffectNone;
  uint32_t mask = 0;
  std::stringstream items(list);
  std::string item;
  bool any = false;
  while (std::getline(items, item, ',')) {
    bool known = false;
    for (const EffectName& e : kEffects)
      if (item == e.name) mask |= e.bit, known = true;
    if (!known)
      throw InputError(where + ": unknown effect \"" + item +
                       "\" (expected a comma-separated list of shadows, reflections, refractions, or all, or none)");
    any = true;
  }
  if (!any)
    throw InputError(where + ": expected all, none, or a comma-separated list of shadows, reflections, refractions");
  return static_cast<Effects>(mask);
}

std::string effects_text(Effects mask) {
  if (mask == kEffectAll) return "all";
  std::string out;
  for (const EffectName& e : kEffects)
    if (mask & e.bit) out += (out.empty() ? "" : ",") + std::string(e.name);
  return out.empty() ? "none" : out;
}

std::string effects_name(Effects mask) {
  if (mask == kEffectAll) return "all";
  std::string out = "shading";
  for (const EffectName& e : kEffects)
    if (mask & e.bit) out += std::string(" + ") + e.name;
  return out == "shading" ? "shading only" : out;
}

}  // namespace tracer
