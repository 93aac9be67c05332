// Names of the Whitted effects that `--effects` and `tracer bench device` switch
// (EffectBit in kernel/scene/scene_view.h): "shadows,reflections", "all", "none".
#pragma once
#include <cstdint>
#include <string>

namespace tracer {

uint32_t parse_effects(const std::string& list);  // InputError naming --effects
std::string effects_name(uint32_t mask);           // "shading only", "shadows + reflections", "all"

}  // namespace tracer
