#include "scene/gltf_schema.h"

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <vector>

namespace tracer {
namespace {

// Uint: a whole number tinygltf keeps in an int (every index, enum and texCoord), so at most
// 2^31 - 1 (4294967295 wrapped to -1, "none"); Size: one it keeps in a size_t (byte offsets,
// lengths and strides, element counts).
enum class Kind {
  String,
  Uint,
  Size,
  Number,
  Bool,
  NumberArray,
  UintArray,
  StringArray,
  UintValues,
  Object,
  ObjectArray
};

struct Rule {
  const char* key;
  Kind kind;
  const char* context = "";  // Object and ObjectArray: the context of the object(s), "" for any
};

// glTF 2.0's properties by the object that holds them (section 5, "Properties Reference").
const std::map<std::string, std::vector<Rule>>& rules() {
  using K = Kind;
  static const std::vector<Rule> texture_info = {
      {"index", K::Uint}, {"texCoord", K::Uint}, {"scale", K::Number}, {"strength", K::Number}};
  static const std::map<std::string, std::vector<Rule>> table = {
      {"root",
       {{"asset", K::Object, "asset"},
        {"scene", K::Uint},
        {"scenes", K::ObjectArray, "scene"},
        {"nodes", K::ObjectArray, "node"},
        {"meshes", K::ObjectArray, "mesh"},
        {"materials", K::ObjectArray, "material"},
        {"accessors", K::ObjectArray, "accessor"},
        {"bufferViews", K::ObjectArray, "bufferView"},
        {"buffers", K::ObjectArray, "buffer"},
        {"textures", K::ObjectArray, "texture"},
        {"images", K::ObjectArray, "image"},
        {"samplers", K::ObjectArray, "sampler"},
        {"cameras", K::ObjectArray, "camera"},
        {"skins", K::ObjectArray},
        {"animations", K::ObjectArray},
        {"extensionsUsed", K::StringArray},
        {"extensionsRequired", K::StringArray}}},
      {"asset",
       {{"version", K::String}, {"minVersion", K::String}, {"generator", K::String}, {"copyright", K::String}}},
      {"scene", {{"nodes", K::UintArray}}},
      {"node",
       {{"camera", K::Uint},
        {"children", K::UintArray},
        {"skin", K::Uint},
        {"matrix", K::NumberArray},
        {"mesh", K::Uint},
        {"rotation", K::NumberArray},
        {"scale", K::NumberArray},
        {"translation", K::NumberArray},
        {"weights", K::NumberArray}}},
      {"mesh", {{"primitives", K::ObjectArray, "primitive"}, {"weights", K::NumberArray}}},
      {"primitive",
       {{"attributes", K::UintValues},
        {"indices", K::Uint},
        {"material", K::Uint},
        {"mode", K::Uint},
        {"targets", K::ObjectArray}}},
      {"material",
       {{"pbrMetallicRoughness", K::Object, "pbr"},
        {"normalTexture", K::Object, "textureInfo"},
        {"occlusionTexture", K::Object, "textureInfo"},
        {"emissiveTexture", K::Object, "textureInfo"},
        {"emissiveFactor", K::NumberArray},
        {"alphaMode", K::String},
        {"alphaCutoff", K::Number},
        {"doubleSided", K::Bool}}},
      {"pbr",
       {{"baseColorFactor", K::NumberArray},
        {"baseColorTexture", K::Object, "textureInfo"},
        {"metallicFactor", K::Number},
        {"roughnessFactor", K::Number},
        {"metallicRoughnessTexture", K::Object, "textureInfo"}}},
      {"textureInfo", texture_info},
      {"accessor",
       {{"bufferView", K::Uint},
        {"byteOffset", K::Size},
        {"componentType", K::Uint},
        {"normalized", K::Bool},
        {"count", K::Size},
        {"type", K::String},
        {"max", K::NumberArray},
        {"min", K::NumberArray},
        {"sparse", K::Object, "sparse"}}},
      {"sparse", {{"count", K::Uint}, {"indices", K::Object, "sparsePart"}, {"values", K::Object, "sparsePart"}}},
      {"sparsePart", {{"bufferView", K::Uint}, {"byteOffset", K::Uint}, {"componentType", K::Uint}}},
      {"bufferView",
       {{"buffer", K::Uint},
        {"byteOffset", K::Size},
        {"byteLength", K::Size},
        {"byteStride", K::Size},
        {"target", K::Uint}}},
      {"buffer", {{"uri", K::String}, {"byteLength", K::Size}}},
      {"texture", {{"sampler", K::Uint}, {"source", K::Uint}}},
      {"image", {{"uri", K::String}, {"mimeType", K::String}, {"bufferView", K::Uint}}},
      {"sampler", {{"magFilter", K::Uint}, {"minFilter", K::Uint}, {"wrapS", K::Uint}, {"wrapT", K::Uint}}},
      {"camera",
       {{"type", K::String}, {"perspective", K::Object, "projection"}, {"orthographic", K::Object, "projection"}}},
      {"projection",
       {{"aspectRatio", K::Number},
        {"yfov", K::Number},
        {"zfar", K::Number},
        {"znear", K::Number},
        {"xmag", K::Number},
        {"ymag", K::Number}}},
      {"", {}},
  };
  return table;
}

// The extensions the reader understands (docs/gltf.md); a file that requires another is refused.
const std::vector<std::string>
    kReadExtensions = {"KHR_lights_punctual",        "KHR_materials_emissive_strength", "KHR_materials_ior",
                       "KHR_materials_transmission", "KHR_materials_specular",          "KHR_texture_transform",
                       "KHR_mesh_quantization"};  // integer attributes: the accessors read every component type

// The properties an object must have (glTF 2.0's schema, "required").
const std::map<std::string, std::vector<const char*>>& required() {
  static const std::map<std::string, std::vector<const char*>> table = {
      {"root", {"asset"}},
      {"asset", {"version"}},
      {"mesh", {"primitives"}},
      {"primitive", {"attributes"}},
      {"accessor", {"componentType", "count", "type"}},
      {"sparse", {"count", "indices", "values"}},
      {"sparsePart", {"bufferView"}},
      {"bufferView", {"buffer", "byteLength"}},
      {"buffer", {"byteLength"}},
      {"textureInfo", {"index"}},
      {"camera", {"type"}},
  };
  return table;
}

constexpr uint64_t kMaxIndex = 2147483647;       // tinygltf's int
constexpr uint64_t kMaxSize = 9007199254740991;  // 2^53 - 1: what a double holds exactly

template <class Test>
bool every(Json& v, Test test) {
  return v.is_array() && std::all_of(v.begin(), v.end(), test);
}

// A whole number from 0 to `most`. JSON does not tell 12 from 12.0, and glTF's schema calls
// both an integer: an integral float counts, and becomes an integer for tinygltf.
bool whole(Json& v, uint64_t most = kMaxSize) {
  if (v.is_number_unsigned()) return v.get<uint64_t>() <= most;
  if (!v.is_number_float()) return false;
  const double d = v.get<double>();
  if (!(d >= 0.0 && d <= static_cast<double>(most) && d == static_cast<double>(static_cast<uint64_t>(d)))) return false;
  v = static_cast<uint64_t>(d);
  return true;
}

bool index_number(Json& v) { return whole(v, kMaxIndex); }

bool has_kind(Json& v, Kind kind) {
  switch (kind) {
    case Kind::String: return v.is_string();
    case Kind::Uint: return index_number(v);
    case Kind::Size: return whole(v);
    case Kind::Number: return v.is_number();
    case Kind::Bool: return v.is_boolean();
    case Kind::NumberArray: return every(v, [](const Json& e) { return e.is_number(); });
    case Kind::UintArray: return every(v, [](Json& e) { return index_number(e); });
    case Kind::StringArray: return every(v, [](const Json& e) { return e.is_string(); });
    case Kind::UintValues:
      return v.is_object() && std::all_of(v.begin(), v.end(), [](Json& e) { return index_number(e); });
    case Kind::Object: return v.is_object();
    case Kind::ObjectArray: return every(v, [](const Json& e) { return e.is_object(); });
  }
  return false;
}

const char* kind_name(Kind kind) {
  switch (kind) {
    case Kind::String: return "a string";
    case Kind::Uint: return "a whole number from 0 to 2147483647";
    case Kind::Size: return "a whole number >= 0";
    case Kind::Number: return "a number";
    case Kind::Bool: return "true or false";
    case Kind::NumberArray: return "an array of numbers";
    case Kind::UintArray: return "an array of whole numbers from 0 to 2147483647";
    case Kind::StringArray: return "an array of strings";
    case Kind::UintValues: return "an object of whole numbers from 0 to 2147483647";
    case Kind::Object: return "an object";
    case Kind::ObjectArray: return "an array of objects";
  }
  return "";
}

std::string child(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

void check_object(Json& object, const std::string& context, const std::string& path, const std::string& file) {
  const std::vector<Rule>& table = rules().at(context);
  if (const auto must = required().find(context); must != required().end())
    for (const char* key : must->second)
      if (!object.contains(key)) fail_at(file, child(path, key), "is missing; glTF 2.0 requires it");
  for (auto item : object.items()) {
    const std::string at = child(path, item.key());
    Json& v = item.value();
    if (item.key() == "name" && !v.is_string()) fail_at(file, at, "expected a string, got " + describe(v));
    if (item.key() == "extensions") {
      if (!v.is_object()) fail_at(file, at, "expected an object, got " + describe(v));
      for (auto ext : v.items()) {
        if (!ext.value().is_object())
          fail_at(file, child(at, ext.key()), "expected an object, got " + describe(ext.value()));
        // The references inside the extensions the tracer reads: KHR_lights_punctual's light,
        // KHR_texture_transform's texCoord (tinygltf keeps both in an int), texture infos.
        for (auto part : ext.value().items()) {
          if ((part.key() == "light" || part.key() == "texCoord") && !index_number(part.value()))
            fail_at(file, child(child(at, ext.key()), part.key()),
                    std::string("expected ") + kind_name(Kind::Uint) + ", got " + describe(part.value()));
          if (part.value().is_object() && part.key().size() > 7 &&
              part.key().compare(part.key().size() - 7, 7, "Texture") == 0)
            check_object(part.value(), "textureInfo", child(child(at, ext.key()), part.key()), file);
        }
      }
    }
    const auto rule = std::find_if(table.begin(), table.end(), [&](const Rule& r) { return item.key() == r.key; });
    if (rule == table.end()) continue;  // extras, and properties the tracer neither reads nor follows
    if (!has_kind(v, rule->kind))
      fail_at(file, at, std::string("expected ") + kind_name(rule->kind) + ", got " + describe(v));
    if (rule->kind == Kind::Object && *rule->context) check_object(v, rule->context, at, file);
    if (rule->kind == Kind::ObjectArray && *rule->context)
      for (size_t i = 0; i < v.size(); ++i) check_object(v[i], rule->context, at + "[" + std::to_string(i) + "]", file);
  }
}

}  // namespace

bool gltf_extension_read(const std::string& name) {
  return std::find(kReadExtensions.begin(), kReadExtensions.end(), name) != kReadExtensions.end();
}

void check_gltf_schema(Json& root, const std::string& file) {
  if (!root.is_object()) fail_at(file, "", "a glTF file is a JSON object, got " + describe(root));
  check_object(root, "root", "", file);
  if (const auto it = root.find("extensionsRequired"); it != root.end())
    for (size_t i = 0; i < it->size(); ++i) {
      const std::string name = (*it)[i].get<std::string>();
      if (!gltf_extension_read(name))
        fail_at(file, "extensionsRequired[" + std::to_string(i) + "]",
                "the file requires " + name + ", which the tracer does not read");
    }
}

}  // namespace tracer
