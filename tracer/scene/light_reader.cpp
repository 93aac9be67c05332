#include "scene/light_reader.h"

#include "scene/scene_types.h"

namespace tracer {

Light read_light(const Json& value, const std::string& path, const std::string& file,
                 std::set<std::string>& used_types) {
  JsonObject obj(value, path, file);
  const std::string type = obj.string("type");
  if (!is_accepted_type("light", type))
    obj.fail("type", "unknown light type \"" + type + "\" (expected " + expected_types("light") +
                         "; emissive shapes are area lights)");
  used_types.insert("light:" + type);
  Light l{};
  l.kind = LightKind::Point;
  l.position = obj.vec3("position");
  l.intensity = obj.color("intensity");
  if (obj.find("attenuation")) {
    const Vec3 k = obj.vec3("attenuation");
    if (k.x < 0 || k.y < 0 || k.z < 0 || (k.x == 0 && k.y == 0 && k.z == 0))
      obj.fail("attenuation", "expected [kc, kl, kq] >= 0, not all zero");
    l.kc = k.x, l.kl = k.y, l.kq = k.z;
    l.has_attenuation = 1;
  }
  obj.finish();
  return l;
}

Background read_background(const Json* value, const std::string& file, std::string& type, TextureLoader& textures) {
  Background bg{BackgroundKind::Constant,
                {0, 0, 0},
                {0, 0, 0},
                {kNoTexture, kNoTexture, kNoTexture, kNoTexture, kNoTexture, kNoTexture}};
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
  }
  obj.finish();
  return bg;
}

}  // namespace tracer
