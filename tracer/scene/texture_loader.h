// Material colours that may be textures (docs/scene-format.md): [r, g, b], {"texture": FILE,
// optional "wrap": "repeat" (default) or "clamp"} with FILE relative to the scene file, or
// {"checker": {"scale": S, "even": RGB, "odd": RGB}}. Each image file is read once with
// OpenImageIO into scene.texels as linear RGB: 8- and 16-bit images are sRGB-decoded,
// float images taken as they are; 1-channel images are grey, a 4th channel is ignored. The
// colour itself is set to the texture's mean, the value light power and debug views use.
#pragma once
#include <map>
#include <string>
#include <tuple>

#include "io/json_reader.h"
#include "scene/scene.h"

namespace tracer {

class TextureLoader {
 public:
  TextureLoader(Scene& scene, std::string scene_dir) : scene_(scene), dir_(std::move(scene_dir)) {}

  // `texture` becomes kNoTexture or the index of the colour's texture.
  Vec3 colour(JsonObject& obj, const std::string& key, uint32_t& texture);
  Vec3 colour_or(JsonObject& obj, const std::string& key, Vec3 fallback, uint32_t& texture);

  // The six faces of a cubemap background (`faces`: +x, -x, +y, -y, +z, -z): square images
  // of one size, clamped at their edges.
  void cube_faces(JsonObject& background, uint32_t faces[6]);

  // An equirectangular environment map at `path` (resolved already): repeated around, clamped
  // at the poles. `where` names the scene key or command-line flag in errors.
  uint32_t environment_map(const std::string& where, const std::string& path);

  std::string resolve(const std::string& file) const;  // relative to the scene file

  // A data map (normal, bump or specular map: `key` is an image file, read without sRGB
  // decoding); kNoTexture when the key is absent.
  uint32_t data_map(JsonObject& obj, const std::string& key);

  // An alpha map (Material::alpha_map): the image's alpha channel where it has four channels,
  // else its first, as a grey texture; `path` resolved already, `where` names it in errors.
  uint32_t alpha_map(const std::string& where, const std::string& path);

  // An image given by a path usable as it is (MTL maps, resolved against the OBJ's
  // directory); `where` names the scene key in errors.
  uint32_t image_file(const std::string& where, const std::string& path, bool data, Vec3& mean);

 private:
  // `where` is the key path errors name; `path` is resolved already.
  uint32_t image(const std::string& where, const std::string& path, TextureWrap wrap_u, TextureWrap wrap_v, Vec3& mean,
                 bool data = false, bool alpha = false);

  Scene& scene_;
  std::string dir_;
  std::map<std::tuple<std::string, TextureWrap, TextureWrap, bool, bool>, std::pair<uint32_t, Vec3>> loaded_;
};

// The sRGB transfer function's inverse (IEC 61966-2-1), with det_pow.
float srgb_to_linear(float c);

}  // namespace tracer
