#include "scene/light_reader.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "scene/scene_types.h"

namespace tracer {

std::string set_light_direction(Light& light, Vec3 d) {
  const double x = d.x, y = d.y, z = d.z, length = std::sqrt(x * x + y * y + z * z);
  if (!(length > 0.0) || !std::isfinite(length)) return "expected a finite, non-zero direction";
  light.direction = {static_cast<float>(x / length), static_cast<float>(y / length), static_cast<float>(z / length)};
  return "";
}

std::string set_spot_cone(Light& light, double inner, double outer) {
  if (!(inner >= 0.0 && inner <= outer && outer <= kPi / 2.0))
    return "expected cone half-angles 0 <= inner <= outer <= 90 degrees";
  light.cos_inner = static_cast<float>(std::cos(inner));
  light.cos_outer = static_cast<float>(std::cos(outer));
  return "";
}

std::string set_sun_disc(Light& light, double diameter) {
  if (diameter == 0.0) {
    light.one_minus_cos = 0.0f;
    return "";
  }
  if (!(diameter >= kMinSunDiameter && diameter <= kPi))
    return "expected an angular diameter of 0 (parallel light) or 0.01 to 180 degrees";
  const double s = std::sin(diameter / 4.0), w = 2.0 * s * s;  // 1 - cos(diameter / 2)
  const double brightest = std::max({light.intensity.x, light.intensity.y, light.intensity.z});
  if (!(brightest / (kPi * w * (2.0 - w)) < FLT_MAX / 16.0))
    return "the disc's radiance, irradiance / (pi sin^2 of its radius), overflows";
  light.one_minus_cos = static_cast<float>(w);
  return "";
}

namespace {

// The point and spot lights' optional [kc, kl, kq].
void read_attenuation(JsonObject& obj, Light& l) {
  if (!obj.find("attenuation")) return;
  const Vec3 k = obj.vec3("attenuation");
  if (k.x < 0 || k.y < 0 || k.z < 0 || (k.x == 0 && k.y == 0 && k.z == 0))
    obj.fail("attenuation", "expected [kc, kl, kq] >= 0, not all zero");
  l.kc = k.x, l.kl = k.y, l.kq = k.z;
  l.has_attenuation = 1;
}

void read_direction(JsonObject& obj, Light& l) {
  if (const std::string why = set_light_direction(l, obj.vec3("direction")); !why.empty()) obj.fail("direction", why);
}

constexpr double kDegree = kPi / 180.0;

}  // namespace

Light read_light(const Json& value, const std::string& path, const std::string& file,
                 std::set<std::string>& used_types) {
  JsonObject obj(value, path, file);
  const std::string type = obj.string("type");
  if (!is_accepted_type("light", type))
    obj.fail("type", "unknown light type \"" + type + "\" (expected " + expected_types("light") +
                         "; emissive shapes are area lights)");
  used_types.insert("light:" + type);
  Light l{};
  l.kind = *declared_light_kind(type);  // accepted: a declared light's type
  if (l.kind == LightKind::Directional) {
    read_direction(obj, l);
    l.intensity = obj.color("irradiance");
    if (const std::string why = set_sun_disc(l, obj.number_or("angle", 0.0f) * kDegree); !why.empty())
      obj.fail("angle", why);
  } else {
    l.position = obj.vec3("position");
    l.intensity = obj.color("intensity");
    read_attenuation(obj, l);
    if (l.kind == LightKind::Spot) {
      read_direction(obj, l);
      const double inner = obj.number_or("inner_angle", 0.0f) * kDegree,
                   outer = obj.number_or("outer_angle", 45.0f) * kDegree;
      if (const std::string why = set_spot_cone(l, inner, outer); !why.empty())
        obj.fail(obj.find("outer_angle") ? "outer_angle" : "inner_angle", why);
    }
  }
  obj.finish();
  return l;
}

Background constant_background(Vec3 radiance) {
  return {BackgroundKind::Constant,
          radiance,
          {0, 0, 0},
          {kNoTexture, kNoTexture, kNoTexture, kNoTexture, kNoTexture, kNoTexture},
          kNoTexture,
          1.0f,
          0.0f};
}

std::string set_environment(Background& bg, uint32_t map, double degrees, double strength) {
  if (!std::isfinite(degrees) || std::abs(degrees) > 1e6) return "rotation: expected degrees from -1e6 to 1e6";
  if (!(strength >= 0.0 && strength <= 1e6)) return "strength: expected a number from 0 to 1e6";
  bg = constant_background({static_cast<float>(strength), static_cast<float>(strength), static_cast<float>(strength)});
  bg.kind = BackgroundKind::Environment;
  bg.map = map;
  const double turn = std::fmod(degrees, 360.0);
  if (std::fmod(turn, 90.0) == 0.0) {  // a quarter turn exactly, so a scene turned with it draws the same
    const int quarter = (static_cast<int>(turn / 90.0) + 4) % 4;
    const float cosines[4] = {1.0f, 0.0f, -1.0f, 0.0f}, sines[4] = {0.0f, 1.0f, 0.0f, -1.0f};
    bg.cos_turn = cosines[quarter];
    bg.sin_turn = sines[quarter];
  } else {
    bg.cos_turn = static_cast<float>(std::cos(turn * M_PI / 180.0));
    bg.sin_turn = static_cast<float>(std::sin(turn * M_PI / 180.0));
  }
  return "";
}

Background read_background(const Json* value, const std::string& file, std::string& type, TextureLoader& textures) {
  Background bg = constant_background({0, 0, 0});
  type = "constant";
  if (!value) return bg;
  JsonObject obj(*value, "background", file);
  type = obj.string("type");
  read_type(obj, "background");
  if (type == "constant") {
    bg.radiance = obj.color("radiance");
  } else if (type == "gradient") {
    bg.kind = BackgroundKind::Gradient;
    bg.radiance = obj.color("zenith");
    bg.horizon = obj.color("horizon");
  } else if (type == "cubemap") {
    bg.kind = BackgroundKind::Cubemap;
    textures.cube_faces(obj, bg.faces);
  } else if (type == "environment") {
    const uint32_t map = textures.environment_map(obj.child("file"), textures.resolve(obj.string("file")));
    const std::string why = set_environment(bg, map, obj.number_or("rotation", 0.0f), obj.number_or("strength", 1.0f));
    if (!why.empty()) obj.fail(why.substr(0, why.find(':')), why.substr(why.find(':') + 2));
  }
  obj.finish();
  return bg;
}

}  // namespace tracer
