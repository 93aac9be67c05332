#include "scene/gltf_materials.h"

#include <algorithm>
#include <cmath>

#include "io/json_reader.h"
#include "kernel/base/detmath.h"
#include "scene/texture_loader.h"

namespace tracer {
namespace {

[[noreturn]] void fail(const GltfFile& file, const std::string& path, const std::string& message) {
  fail_at(file.path, path, message);
}

float unit_factor(const GltfFile& file, double v, const std::string& path) {
  if (!(v >= 0.0 && v <= 1.0)) fail(file, path, "must be in [0, 1], got " + std::to_string(v));
  return static_cast<float>(v);
}

Vec3 unit_colour(const GltfFile& file, const std::vector<double>& v, size_t size, const std::string& path) {
  if (v.size() != size) fail(file, path, "expected " + std::to_string(size) + " numbers");
  return {unit_factor(file, v[0], path + "[0]"), unit_factor(file, v[1], path + "[1]"),
          unit_factor(file, v[2], path + "[2]")};
}

const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions, const std::string& name) {
  const auto it = extensions.find(name);
  return it == extensions.end() || !it->second.IsObject() ? nullptr : &it->second;
}

// A number of an extension's object, or `fallback` when absent; errors name `path`.
double extension_number(const GltfFile& file, const tinygltf::Value& ext, const std::string& key, double fallback,
                        const std::string& path) {
  if (!ext.Has(key)) return fallback;
  const tinygltf::Value& v = ext.Get(key);
  if (!v.IsNumber()) fail(file, path + "." + key, "expected a number");
  const double d = v.GetNumberAsDouble();
  if (!std::isfinite(d)) fail(file, path + "." + key, "must be finite");
  return d;
}

// KHR_texture_transform of a texture reference, if it has one.
bool read_uv_transform(const GltfFile& file, const tinygltf::ExtensionMap& extensions, const std::string& path,
                       GltfUvTransform& out) {
  const tinygltf::Value* ext = extension(extensions, "KHR_texture_transform");
  if (!ext) return false;
  const std::string at = path + ".extensions.KHR_texture_transform";
  const auto pair = [&](const std::string& key, float fallback, float into[2]) {
    into[0] = into[1] = fallback;
    if (!ext->Has(key)) return;
    const tinygltf::Value& v = ext->Get(key);
    if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber())
      fail(file, at + "." + key, "expected two numbers");
    for (int i = 0; i < 2; ++i)
      into[i] = gltf_float(file, v.Get(i).GetNumberAsDouble(), at + "." + key + "[" + std::to_string(i) + "]");
  };
  float scale[2];
  pair("offset", 0.0f, out.offset);
  pair("scale", 1.0f, scale);
  const float rotation = gltf_float(file, extension_number(file, *ext, "rotation", 0.0, at), at + ".rotation");
  float s, c;
  det_sincos(rotation, s, c);
  // T R S with R = [[cos, sin], [-sin, cos]] (the extension's matrix, row by row).
  out.m[0][0] = c * scale[0], out.m[0][1] = s * scale[1];
  out.m[1][0] = -s * scale[0], out.m[1][1] = c * scale[1];
  return true;
}

bool same_transform(const GltfUvTransform& a, const GltfUvTransform& b) {
  return a.m[0][0] == b.m[0][0] && a.m[0][1] == b.m[0][1] && a.m[1][0] == b.m[1][0] && a.m[1][1] == b.m[1][1] &&
         a.offset[0] == b.offset[0] && a.offset[1] == b.offset[1];
}

}  // namespace

void GltfUvTransform::apply(float uv[2]) const {
  const float u = uv[0], v = uv[1];
  uv[0] = offset[0] + (m[0][0] * u + m[0][1] * v);
  uv[1] = offset[1] + (m[1][0] * u + m[1][1] * v);
}

void GltfMaterials::ignore(const std::string& what) {
  if (ignored_seen_.insert(what).second) ignored_.push_back(what);
}

uint32_t GltfMaterials::texels(int source, Decode decode, const std::string& path) {
  const auto key = std::make_pair(source, static_cast<int>(decode));
  if (const auto known = texels_.find(key); known != texels_.end()) return known->second;
  auto image = images_.find(source);
  if (image == images_.end()) image = images_.emplace(source, decode_gltf_image(file_, source, path)).first;
  const ImagePixels& pixels = image->second;
  const uint32_t offset = static_cast<uint32_t>(scene_.texels.size());
  const bool srgb = decode == Decode::Colour && !pixels.float_format;
  for (size_t p = 0; p < size_t{pixels.width} * pixels.height; ++p)
    for (int c = 0; c < 3; ++c) {
      float v = decode == Decode::Alpha ? (pixels.channels_read == 4 ? pixels.values[p * 4 + 3] : 1.0f)
                                        : pixels.values[p * pixels.channels_read + (pixels.channels_read < 3 ? 0 : c)];
      if (!std::isfinite(v)) fail(file_, path, "its image holds a texel that is not finite");
      if (srgb) v = srgb_to_linear(v);
      if (decode == Decode::Colour) v = std::max(v, 0.0f);
      scene_.texels.push_back(v);
    }
  texels_.emplace(key, offset);
  return offset;
}

GltfMaterials::Baked GltfMaterials::texture(int index, int tex_coord, Bake bake, Vec3 factor, const std::string& use) {
  if (index < 0 || static_cast<size_t>(index) >= file_.model.textures.size())
    fail(file_, use + ".index",
         "names texture " + std::to_string(index) + "; the file has " + std::to_string(file_.model.textures.size()));
  if (tex_coord != 0) {
    ignore(use + ": texCoord " + std::to_string(tex_coord) + " (only TEXCOORD_0 is read; the texture is left out)");
    return {kNoTexture, factor};
  }
  const auto key = std::make_tuple(index, static_cast<int>(bake), factor.x, factor.y, factor.z);
  if (const auto known = textures_.find(key); known != textures_.end()) return known->second;
  const tinygltf::Texture& t = file_.model.textures[index];
  const std::string path = "textures[" + std::to_string(index) + "]";
  if (t.source < 0) fail(file_, path + ".source", "missing: the texture names no image");
  TextureWrap wrap_u = TextureWrap::Repeat, wrap_v = TextureWrap::Repeat;
  if (t.sampler >= 0) {
    if (static_cast<size_t>(t.sampler) >= file_.model.samplers.size())
      fail(file_, path + ".sampler",
           "names sampler " + std::to_string(t.sampler) + "; the file has " +
               std::to_string(file_.model.samplers.size()));
    const tinygltf::Sampler& s = file_.model.samplers[t.sampler];
    const auto wrap = [](int mode) {
      return mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE     ? TextureWrap::Clamp
             : mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT ? TextureWrap::Mirror
                                                             : TextureWrap::Repeat;
    };
    wrap_u = wrap(s.wrapS);
    wrap_v = wrap(s.wrapT);
  }
  // Each image's texels once per decoding; each use's factor applied after filtering.
  const Decode decode = bake == Bake::SrgbTimes ? Decode::Colour : bake == Bake::Alpha ? Decode::Alpha : Decode::Data;
  const uint32_t offset = texels(t.source, decode, path);
  const ImagePixels& pixels = images_.at(t.source);
  Texture tex = image_texture(pixels.width, pixels.height, offset, wrap_u, wrap_v);
  if (bake == Bake::SrgbTimes) tex.times = factor;
  // The normal map's scale multiplies x and y of the unpacked normal 2c - 1 (glTF 2.0, 3.9.3):
  // c s + (1 - s) / 2.
  if (bake == Bake::LinearNormal && factor.x != 1.0f) {
    tex.times = {factor.x, factor.x, 1.0f};
    tex.plus = {(1.0f - factor.x) * 0.5f, (1.0f - factor.x) * 0.5f, 0.0f};
  }
  // A colour's mean at texel centres, its stand-in where the material keeps one colour (the
  // other uses read the texture alone).
  Baked baked{static_cast<uint32_t>(scene_.textures.size()), factor};
  if (bake == Bake::SrgbTimes) {
    double sum[3] = {0, 0, 0};
    const size_t count = size_t{pixels.width} * pixels.height;
    for (size_t p = 0; p < count; ++p)
      for (int c = 0; c < 3; ++c) sum[c] += scene_.texels[offset + p * 3 + c] * tex.times[c];
    const double n = static_cast<double>(count);
    baked.mean = {float(sum[0] / n), float(sum[1] / n), float(sum[2] / n)};
  }
  scene_.textures.push_back(tex);
  scene_.features |= kFeatureTextures;
  scene_.report.used_types.insert(bake == Bake::SrgbTimes      ? "texture:image"
                                  : bake == Bake::LinearNormal ? "texture:normal_map"
                                  : bake == Bake::Alpha        ? "texture:alpha_map"
                                                               : "texture:metal_rough_map");
  textures_.emplace(key, baked);
  return baked;
}

Material GltfMaterials::convert(const tinygltf::Material& g, const std::string& path, GltfUvTransform& uv) {
  Material m = plain_material(MaterialKind::GltfMetalRough);
  m.fresnel = FresnelKind::Schlick;
  const tinygltf::PbrMetallicRoughness& pbr = g.pbrMetallicRoughness;
  const std::string pbr_path = path + ".pbrMetallicRoughness";
  const Vec3 base = unit_colour(file_, pbr.baseColorFactor, 4, pbr_path + ".baseColorFactor");
  m.albedo = base;
  m.metallic = unit_factor(file_, pbr.metallicFactor, pbr_path + ".metallicFactor");
  m.roughness = unit_factor(file_, pbr.roughnessFactor, pbr_path + ".roughnessFactor");
  m.ior = 1.5f;
  if (const tinygltf::Value* ior = extension(g.extensions, "KHR_materials_ior")) {
    const double v = extension_number(file_, *ior, "ior", 1.5, path + ".extensions.KHR_materials_ior");
    if (!(v >= 1.0 && v <= 10.0)) fail(file_, path + ".extensions.KHR_materials_ior.ior", "must be in [1, 10]");
    m.ior = static_cast<float>(v);
  }
  if (const tinygltf::Value* tr = extension(g.extensions, "KHR_materials_transmission")) {
    const std::string at = path + ".extensions.KHR_materials_transmission";
    m.transmission =
        unit_factor(file_, extension_number(file_, *tr, "transmissionFactor", 0.0, at), at + ".transmissionFactor");
    if (tr->Has("transmissionTexture")) ignore(at + ".transmissionTexture (the factor alone is used)");
  }

  // One uv transform per material: the first texture's that has one.
  bool has_transform = false;
  const auto transform_of = [&](const tinygltf::ExtensionMap& ext, const std::string& at) {
    GltfUvTransform t;
    if (!read_uv_transform(file_, ext, at, t)) return;
    if (!has_transform)
      uv = t, has_transform = true;
    else if (!same_transform(uv, t))
      ignore(at + ": a second, different KHR_texture_transform (the first is used)");
  };
  if (pbr.baseColorTexture.index >= 0) {
    const std::string at = pbr_path + ".baseColorTexture";
    transform_of(pbr.baseColorTexture.extensions, at);
    const Baked b = texture(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, Bake::SrgbTimes, base, at);
    m.texture[kSlotAlbedo] = b.texture;
    m.albedo = b.mean;
  }
  if (pbr.metallicRoughnessTexture.index >= 0) {
    const std::string at = pbr_path + ".metallicRoughnessTexture";
    transform_of(pbr.metallicRoughnessTexture.extensions, at);
    m.factor_map =
        texture(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord, Bake::Linear, {1, 1, 1}, at)
            .texture;
  }
  if (g.normalTexture.index >= 0) {
    const std::string at = path + ".normalTexture";
    transform_of(g.normalTexture.extensions, at);
    const float scale = gltf_float(file_, g.normalTexture.scale, at + ".scale");
    m.normal_map =
        texture(g.normalTexture.index, g.normalTexture.texCoord, Bake::LinearNormal, {scale, scale, scale}, at).texture;
  }
  if (const tinygltf::Value* sp = extension(g.extensions, "KHR_materials_specular")) {
    // A dielectric without its specular layer is Lambert's diffuse surface: read as such.
    const std::string at = path + ".extensions.KHR_materials_specular";
    if (extension_number(file_, *sp, "specularFactor", 1.0, at) == 0.0 && m.metallic == 0.0f &&
        m.transmission == 0.0f && m.factor_map == kNoTexture)
      m.kind = MaterialKind::Lambert;
    else
      ignore(at + " (read only as specularFactor 0 on a dielectric: a Lambert surface)");
  }
  if (g.occlusionTexture.index >= 0) ignore(path + ".occlusionTexture (the tracer computes occlusion)");
  if (g.alphaMode == "MASK" || g.alphaMode == "BLEND") {
    m.alpha_mode = g.alphaMode == "MASK" ? AlphaMode::Mask : AlphaMode::Blend;
    m.alpha = pbr.baseColorFactor.size() == 4
                  ? unit_factor(file_, pbr.baseColorFactor[3], pbr_path + ".baseColorFactor")
                  : 1.0f;
    m.alpha_cutoff = unit_factor(file_, g.alphaCutoff, path + ".alphaCutoff");
    if (pbr.baseColorTexture.index >= 0)  // its alpha channel (1 where the image has none)
      m.alpha_map = texture(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, Bake::Alpha, {1, 1, 1},
                            pbr_path + ".baseColorTexture")
                        .texture;
  } else if (g.alphaMode != "OPAQUE") {
    fail(file_, path + ".alphaMode", "expected OPAQUE, MASK or BLEND, got \"" + g.alphaMode + "\"");
  }

  Vec3 emission =
      g.emissiveFactor.empty() ? Vec3{0, 0, 0} : unit_colour(file_, g.emissiveFactor, 3, path + ".emissiveFactor");
  if (const tinygltf::Value* es = extension(g.extensions, "KHR_materials_emissive_strength")) {
    const std::string at = path + ".extensions.KHR_materials_emissive_strength";
    const double strength = extension_number(file_, *es, "emissiveStrength", 1.0, at);
    if (!(strength >= 0.0 && strength <= 1e6)) fail(file_, at + ".emissiveStrength", "must be in [0, 1e6]");
    emission = emission * static_cast<float>(strength);
  }
  if (!(std::max(emission.x, std::max(emission.y, emission.z)) > 0.0f)) return m;
  // glTF adds the emission to the surface's reflection (3.9.3): the material emits, and its
  // triangles are area lights. One that reflects nothing (a black Lambert surface: a lamp)
  // is the tracer's emissive material, the same light without a BSDF to evaluate.
  const bool black = m.kind == MaterialKind::Lambert && m.texture[kSlotAlbedo] == kNoTexture &&
                     std::max(m.albedo.x, std::max(m.albedo.y, m.albedo.z)) == 0.0f;
  if (black) {  // keeping its cut-out
    const Material cut = m;
    m = plain_material(MaterialKind::Emissive);
    m.alpha_mode = cut.alpha_mode, m.alpha = cut.alpha, m.alpha_cutoff = cut.alpha_cutoff, m.alpha_map = cut.alpha_map;
  }
  m.radiance = emission;
  m.two_sided = g.doubleSided ? 1u : 0u;
  if (g.emissiveTexture.index >= 0) {
    const std::string at = path + ".emissiveTexture";
    transform_of(g.emissiveTexture.extensions, at);
    const Baked b = texture(g.emissiveTexture.index, g.emissiveTexture.texCoord, Bake::SrgbTimes, emission, at);
    m.texture[kSlotRadiance] = b.texture;
    if (b.texture != kNoTexture) m.radiance = b.mean;
  }
  return m;
}

uint32_t GltfMaterials::material(int index, GltfUvTransform& uv) {
  if (const auto known = materials_.find(index); known != materials_.end()) {
    uv = known->second.second;
    return known->second.first;
  }
  const size_t kept = file_.model.materials.size();
  if (index >= 0 && static_cast<size_t>(index) >= kept)  // past the kept ones by as much as past the file's
    fail(file_, "materials",
         "material " + std::to_string(file_.materials_in_file + (static_cast<size_t>(index) - kept)) +
             " is named, but the file has " + std::to_string(file_.materials_in_file));
  const std::string path =
      "materials[" + (index < 0 ? std::string("-1") : std::to_string(file_.material_in_file[index])) + "]";
  // The specification's default material (3.9.1): base colour 1, metallic 1, roughness 1.
  const tinygltf::Material fallback;
  uv = GltfUvTransform{};
  const Material m = convert(index < 0 ? fallback : file_.model.materials[index], path, uv);
  const uint32_t id = static_cast<uint32_t>(scene_.materials.size());
  scene_.materials.push_back(m);
  const std::string name = index < 0 ? std::string("(default)") : file_.model.materials[index].name;
  scene_.material_names.push_back(file_.path + ":" + (name.empty() ? path : name));
  scene_.report.used_types.insert(m.kind == MaterialKind::Emissive  ? "material:emissive"
                                  : m.kind == MaterialKind::Lambert ? "material:lambert"
                                                                    : "material:metal_rough");
  if (m.kind != MaterialKind::Emissive && emits(m)) scene_.report.used_types.insert("material:emission");
  materials_.emplace(index, std::make_pair(id, uv));
  return id;
}

}  // namespace tracer
