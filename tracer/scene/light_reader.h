// The scene file's `lights` entries and its `background` (docs/scene-format.md, "Lights" and
// "Background"). Emissive shapes are area lights; they are materials, not entries here.
#pragma once
#include <set>
#include <string>

#include "io/json_reader.h"
#include "kernel/scene/scene_view.h"
#include "scene/texture_loader.h"

namespace tracer {

// Records the light's type in `used_types` ("light:point").
Light read_light(const Json& value, const std::string& path, const std::string& file,
                 std::set<std::string>& used_types);

// The parts of a spot or a sun that the scene file and glTF's KHR_lights_punctual describe
// alike; each returns "" or why the value is refused, for the caller to name its key.
std::string set_light_direction(Light& light, Vec3 direction);  // made unit, in double
// Half-angles in radians, 0 <= inner <= outer <= pi / 2.
std::string set_spot_cone(Light& light, double inner, double outer);
// The sun's angular diameter in radians: 0 (a delta light) or kMinSunDiameter to pi, where
// its radiance E / (pi sin^2 theta_max) stays finite for the irradiance already set.
std::string set_sun_disc(Light& light, double diameter);
constexpr double kMinSunDiameter = 1.7453292519943295e-4;  // 0.01 degrees

// A constant background of that radiance.
Background constant_background(Vec3 radiance);

// An equirectangular background (kernel/light/equirect_map.h) of texture `map`, turned
// `degrees` about +y (exactly at multiples of 90) and scaled by `strength`; "" or
// "KEY: why" for a value refused.
std::string set_environment(Background& bg, uint32_t map, double degrees, double strength);

// A missing background is constant black; `type` receives its type name.
Background read_background(const Json* value, const std::string& file, std::string& type, TextureLoader& textures);

}  // namespace tracer
