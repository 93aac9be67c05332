#include "scene/texture_loader.h"

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "image/image_io.h"
#include "kernel/base/detmath.h"

namespace tracer {

std::string TextureLoader::resolve(const std::string& file) const {
  return (std::filesystem::path(dir_) / file).string();
}

float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : det_pow((c + 0.055f) / 1.055f, 2.4f); }

Vec3 TextureLoader::colour(JsonObject& obj, const std::string& key, uint32_t& texture) {
  texture = kNoTexture;
  const Json& v = obj.get(key);
  if (!v.is_object()) {
    const Vec3 c = read_vec3(v, obj.child(key), obj.file());
    if (c.x < 0.0f || c.y < 0.0f || c.z < 0.0f) obj.fail(key, "colour components must be >= 0");
    return c;
  }
  JsonObject spec(v, obj.child(key), obj.file());
  Vec3 mean{0, 0, 0};
  if (spec.find("texture")) {
    const std::string file = spec.string("texture");
    const std::string wrap = spec.string_or("wrap", "repeat");
    if (wrap != "repeat" && wrap != "clamp")
      spec.fail("wrap", "expected \"repeat\" or \"clamp\", got \"" + wrap + "\"");
    const TextureWrap mode = wrap == "clamp" ? TextureWrap::Clamp : TextureWrap::Repeat;
    texture = image(spec.child("texture"), resolve(file), mode, mode, mean);
    scene_.report.used_types.insert("texture:image");
  } else if (spec.find("checker")) {
    JsonObject checker(spec.get("checker"), spec.child("checker"), obj.file());
    Texture t{};
    t.kind = TextureKind::Checker;
    t.scale = checker.number("scale");
    if (!(t.scale > 0.0f)) checker.fail("scale", "must be > 0");
    uint32_t unused;
    t.even = colour(checker, "even", unused);
    if (unused != kNoTexture) checker.fail("even", "must be [r, g, b]");
    t.odd = colour(checker, "odd", unused);
    if (unused != kNoTexture) checker.fail("odd", "must be [r, g, b]");
    checker.finish();
    mean = (t.even + t.odd) * 0.5f;
    texture = static_cast<uint32_t>(scene_.textures.size());
    scene_.textures.push_back(t);
    scene_.report.used_types.insert("texture:checker");
  } else {
    spec.fail("", "expected [r, g, b], {\"texture\": FILE} or {\"checker\": {...}}");
  }
  spec.finish();
  scene_.features |= kFeatureTextures;
  return mean;
}

Vec3 TextureLoader::colour_or(JsonObject& obj, const std::string& key, Vec3 fallback, uint32_t& texture) {
  texture = kNoTexture;
  return obj.find(key) ? colour(obj, key, texture) : fallback;
}

void TextureLoader::cube_faces(JsonObject& background, uint32_t faces[6]) {
  const Json& list = background.get("faces");
  if (!list.is_array() || list.size() != 6)
    background.fail("faces", "expected six image files (+x, -x, +y, -y, +z, -z), got " + describe(list));
  for (size_t i = 0; i < 6; ++i) {
    const std::string where = background.child("faces") + "[" + std::to_string(i) + "]";
    if (!list[i].is_string()) fail_at(background.file(), where, "expected an image file, got " + describe(list[i]));
    Vec3 mean;
    faces[i] = image(where, resolve(list[i].get<std::string>()), TextureWrap::Clamp, TextureWrap::Clamp, mean);
    const Texture& t = scene_.textures[faces[i]];
    const Texture& first = scene_.textures[faces[0]];
    if (t.width != t.height)
      fail_at(background.file(), where,
              "cube faces must be square, got " + std::to_string(t.width) + "x" + std::to_string(t.height));
    if (t.width != first.width)
      fail_at(background.file(), where,
              "cube faces must all be the same size: " + std::to_string(t.width) + " against " +
                  std::to_string(first.width) + " for faces[0]");
  }
  scene_.features |= kFeatureTextures;
}

uint32_t TextureLoader::image_file(const std::string& where, const std::string& path, bool data, Vec3& mean) {
  scene_.features |= kFeatureTextures;
  if (!data) scene_.report.used_types.insert("texture:image");
  return image(where, path, TextureWrap::Repeat, TextureWrap::Repeat, mean, data);
}

uint32_t TextureLoader::alpha_map(const std::string& where, const std::string& path) {
  Vec3 mean;
  scene_.features |= kFeatureTextures;
  scene_.report.used_types.insert("texture:alpha_map");
  return image(where, path, TextureWrap::Repeat, TextureWrap::Repeat, mean, true, true);
}

uint32_t TextureLoader::environment_map(const std::string& where, const std::string& path) {
  Vec3 mean;
  scene_.features |= kFeatureTextures;
  return image(where, path, TextureWrap::Repeat, TextureWrap::Clamp, mean);
}

uint32_t TextureLoader::data_map(JsonObject& obj, const std::string& key) {
  if (!obj.find(key)) return kNoTexture;
  Vec3 mean;
  const uint32_t index =
      image(obj.child(key), resolve(obj.string(key)), TextureWrap::Repeat, TextureWrap::Repeat, mean, true);
  scene_.features |= kFeatureTextures;
  scene_.report.used_types.insert("texture:" + key);
  return index;
}

uint32_t TextureLoader::image(const std::string& where, const std::string& path, TextureWrap wrap_u, TextureWrap wrap_v,
                              Vec3& mean, bool data, bool alpha) {
  const auto known = loaded_.find({path, wrap_u, wrap_v, data, alpha});
  if (known != loaded_.end()) {
    mean = known->second.second;
    return known->second.first;
  }
  const std::string& scene_file = scene_.file;
  scene_.report.input_files.insert(path);
  if (!std::filesystem::exists(path)) fail_at(scene_file, where, "image " + path + " does not exist");
  if (!std::filesystem::is_regular_file(path)) fail_at(scene_file, where, "image " + path + " is not a regular file");
  ImagePixels pixels;
  try {
    pixels = read_image_pixels(path, 4);
  } catch (const InputError& e) {
    fail_at(scene_file, where, e.what());
  }
  const int channels = pixels.channels;
  if (channels != 1 && channels != 3 && channels != 4)
    fail_at(scene_file, where, path + ": expected 1, 3 or 4 channels, got " + std::to_string(channels));
  const bool srgb = !data && !pixels.float_format;
  const Texture t =
      image_texture(pixels.width, pixels.height, static_cast<uint32_t>(scene_.texels.size()), wrap_u, wrap_v);
  double sum[3] = {0, 0, 0};
  for (size_t p = 0; p < size_t{pixels.width} * pixels.height; ++p)
    for (int c = 0; c < 3; ++c) {
      float v = pixels.values[p * channels + (alpha ? (channels == 4 ? 3 : 0) : channels == 1 ? 0 : c)];
      if (srgb) v = srgb_to_linear(v);
      // A NaN, inf or (in a colour) negative texel would reach the film as NaN or negative light.
      if (!std::isfinite(v) || (!data && v < 0.0f))
        fail_at(scene_file, where,
                path + ": texel (" + std::to_string(p % pixels.width) + ", " + std::to_string(p / pixels.width) +
                    ") channel " + std::to_string(c) + " is " + std::to_string(v) + "; texels must be finite" +
                    (data ? "" : " and >= 0"));
      scene_.texels.push_back(v);
      sum[c] += v;
    }
  const double n = double(pixels.width) * pixels.height;
  mean = {float(sum[0] / n), float(sum[1] / n), float(sum[2] / n)};
  const uint32_t index = static_cast<uint32_t>(scene_.textures.size());
  scene_.textures.push_back(t);
  loaded_[{path, wrap_u, wrap_v, data, alpha}] = {index, mean};
  return index;
}

}  // namespace tracer
