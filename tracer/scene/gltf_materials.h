// glTF materials as the tracer's (docs/gltf.md): pbrMetallicRoughness becomes metal_rough
// (glTF 2.0 appendix B) with KHR_materials_ior and KHR_materials_transmission (and, with
// KHR_materials_specular factor 0 on a dielectric, Lambert's diffuse surface); a material
// that emits (emissiveFactor x KHR_materials_emissive_strength) becomes an emissive area
// light. Each image's texels are stored once per decoding (colour: sRGB-decoded; data; alpha),
// and each use is a texture over them with its factor applied after filtering (the kernel's
// textures replace a colour): base colour and emission times their factors, the normal map
// with its scale, metallicRoughnessTexture as the material's factor map. KHR_texture_transform
// is baked into the mesh's uvs (GltfUvTransform), so it must be one per material.
#pragma once
#include <map>
#include <string>
#include <unordered_set>
#include <vector>

#include "kernel/material/material.h"
#include "scene/gltf_file.h"
#include "scene/scene.h"

namespace tracer {

// uv' = offset + R(rotation) S(scale) uv (KHR_texture_transform), in glTF's uv space
// (v down); the identity when the material has none.
struct GltfUvTransform {
  float m[2][2] = {{1, 0}, {0, 1}};
  float offset[2] = {0, 0};
  void apply(float uv[2]) const;
};

class GltfMaterials {
 public:
  GltfMaterials(const GltfFile& file, Scene& scene) : file_(file), scene_(scene) {}

  // The scene's material id of glTF material `index` (-1: the specification's default
  // material), added on first use; `uv` receives its texture transform.
  uint32_t material(int index, GltfUvTransform& uv);

  // What was read but changes nothing in the image (alpha, mirrored wrap, ...), once each.
  const std::vector<std::string>& ignored() const { return ignored_; }
  size_t texture_count() const { return textures_.size(); }

 private:
  struct Baked {
    uint32_t texture;
    Vec3 mean;  // a colour's mean texel times its factor; other uses: the factor
  };
  // How a use reads the texture glTF's `textures[index]` names: a colour times `factor`, a
  // normal map of scale factor.x, data as it is, the alpha channel.
  enum class Bake { SrgbTimes, LinearNormal, Linear, Alpha };
  Baked texture(int index, int tex_coord, Bake bake, Vec3 factor, const std::string& use);
  // The offset of image `source`'s texels decoded so, stored on first use.
  enum class Decode { Colour, Data, Alpha };
  uint32_t texels(int source, Decode decode, const std::string& path);
  void ignore(const std::string& what);
  Material convert(const tinygltf::Material& m, const std::string& path, GltfUvTransform& uv);

  const GltfFile& file_;
  Scene& scene_;
  std::map<int, std::pair<uint32_t, GltfUvTransform>> materials_;
  std::map<std::tuple<int, int, float, float, float>, Baked> textures_;
  std::map<std::pair<int, int>, uint32_t> texels_;
  std::map<int, ImagePixels> images_;
  std::vector<std::string> ignored_;
  std::unordered_set<std::string> ignored_seen_;
};

}  // namespace tracer
