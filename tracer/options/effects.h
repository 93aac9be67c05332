// Names of the Whitted effects that `--effects`, `render.effects` and `tracer bench device`
// switch (Effects in kernel/scene/render_settings.h): "shadows,reflections", "all", "none".
#pragma once
#include <string>

#include "kernel/scene/render_settings.h"

namespace tracer {

Effects parse_effects(const std::string& list, const std::string& where);  // InputError naming `where`
std::string effects_text(Effects mask);  // the form parse_effects reads back: "all", "none", "shadows,reflections"
std::string effects_name(Effects mask);  // for tables: "shading only", "shading + shadows", "all"

}  // namespace tracer
