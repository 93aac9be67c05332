#include "scene/gltf_normalize.h"

#include <OpenImageIO/strutil.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <vector>

namespace tracer {
namespace {

constexpr const char* kBase64Prefix = "data:application/octet-stream;base64,";

std::string at(const char* array, size_t i) { return std::string(array) + "[" + std::to_string(i) + "]"; }

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

// "data:[<media type>][;base64],<data>" (RFC 2397) in the one form tinygltf decodes.
std::string base64_data_uri(const std::string& uri, const std::string& file, const std::string& path) {
  const size_t comma = uri.find(',');
  if (comma == std::string::npos) fail_at(file, path, "a data URI without the comma that starts its data");
  std::string head = uri.substr(5, comma - 5);
  std::transform(head.begin(), head.end(), head.begin(), [](unsigned char c) { return std::tolower(c); });
  if (head.size() >= 7 && head.compare(head.size() - 7, 7, ";base64") == 0)
    return kBase64Prefix + uri.substr(comma + 1);
  std::string bytes;
  bytes.reserve(uri.size() - comma);
  for (size_t i = comma + 1; i < uri.size(); ++i) {
    if (uri[i] != '%') {
      bytes += uri[i];
      continue;
    }
    const int hi = i + 2 < uri.size() ? hex_digit(uri[i + 1]) : -1, lo = hi >= 0 ? hex_digit(uri[i + 2]) : -1;
    if (lo < 0)
      fail_at(file, path,
              "a data URI with a '%' at character " + std::to_string(i) + " not followed by two hex digits");
    bytes += static_cast<char>(hi * 16 + lo);
    i += 2;
  }
  return kBase64Prefix + OIIO::Strutil::base64_encode(bytes);
}

bool has_uri(const Json& object) {
  const auto uri = object.find("uri");
  return uri != object.end() && !uri->get<std::string>().empty();
}

// Every "extras" (application data, any JSON) and the animations: tinygltf keeps each element
// of them as a Value of about 200 bytes (a 2 MB array of extras took 350 MB), and the tracer
// reads neither. The JSON's depth is at most 64 (the checked parser), so recursion is bounded.
void drop_extras(Json& object) {
  if (object.is_object()) object.erase("extras");
  if (object.is_object() || object.is_array())
    for (Json& child : object) drop_extras(child);
}

// Materials no mesh primitive names are dropped, the others renumbered in order; returns
// each kept material's index in the file, for messages. tinygltf keeps a material in about
// 4 KB, so 300,000 empty ones ("{}", 3 bytes each) took 1.3 GB.
std::vector<uint64_t> drop_unused_materials(Json& root) {
  std::vector<uint64_t> in_file;
  if (!root.contains("materials")) return in_file;
  Json& materials = root["materials"];
  std::vector<int64_t> renumbered(materials.size(), -1);
  if (root.contains("meshes"))
    for (const Json& mesh : root["meshes"])
      for (const Json& prim : mesh["primitives"])
        if (prim.contains("material") && prim["material"].get<uint64_t>() < materials.size())
          renumbered[prim["material"].get<uint64_t>()] = 0;
  Json kept = Json::array();
  for (size_t i = 0; i < materials.size(); ++i) {
    if (renumbered[i] < 0) continue;
    renumbered[i] = static_cast<int64_t>(kept.size());
    in_file.push_back(i);
    kept.push_back(std::move(materials[i]));
  }
  if (root.contains("meshes"))
    for (Json& mesh : root["meshes"])
      for (Json& prim : mesh["primitives"])
        if (prim.contains("material")) {
          const uint64_t m = prim["material"].get<uint64_t>();
          // one past the list stays past it (kept.size() + how far past), for its message
          prim["material"] =
              m < materials.size() ? static_cast<uint64_t>(renumbered[m]) : kept.size() + (m - materials.size());
        }
  materials = std::move(kept);
  return in_file;
}

// Buffers that name one file (their uris alike once normalized: "a.bin", "./a.bin") become
// one, of the largest byteLength among them: tinygltf reads a file once per buffer, so 100
// buffers over one 4 MB file took 376 MB. Their views now name the first of them; the
// others are dropped as unused below.
void share_buffers_of_one_file(Json& root) {
  if (!root.contains("buffers") || !root.contains("bufferViews")) return;
  Json& buffers = root["buffers"];
  std::map<std::string, uint64_t> first_of_file;
  std::vector<uint64_t> shared(buffers.size());
  for (size_t i = 0; i < buffers.size(); ++i) {
    shared[i] = i;
    if (!has_uri(buffers[i])) continue;
    const std::string uri = buffers[i]["uri"].get<std::string>();
    if (uri.rfind("data:", 0) == 0) continue;  // its bytes are in the file itself
    const auto [it, first] = first_of_file.emplace(std::filesystem::path(uri).lexically_normal().string(), i);
    if (first) continue;
    shared[i] = it->second;
    Json& keeper = buffers[it->second];
    keeper["byteLength"] = std::max(keeper["byteLength"].get<uint64_t>(), buffers[i]["byteLength"].get<uint64_t>());
  }
  for (Json& view : root["bufferViews"]) {
    const uint64_t b = view["buffer"].get<uint64_t>();
    if (b < shared.size()) view["buffer"] = shared[b];
  }
}

// Drops the buffers no buffer view names and renumbers the views' references.
void drop_unused_buffers(Json& root, bool binary, const std::string& file) {
  if (!root.contains("buffers")) return;
  Json& buffers = root["buffers"];
  std::set<uint64_t> used;
  if (root.contains("bufferViews"))
    for (const Json& view : root["bufferViews"]) used.insert(view["buffer"].get<uint64_t>());
  std::vector<uint64_t> renumbered(buffers.size());
  Json kept = Json::array();
  for (size_t i = 0; i < buffers.size(); ++i) {
    renumbered[i] = kept.size();
    if (!used.count(i)) continue;
    if (!has_uri(buffers[i]) && !(binary && i == 0))
      fail_at(file, at("buffers", i),
              binary ? "has no uri; only a .glb's first buffer is its binary chunk"
                     : "has no uri; a .gltf's buffers name their data (only a .glb's first buffer may leave it out)");
    kept.push_back(std::move(buffers[i]));
  }
  if (root.contains("bufferViews"))
    for (Json& view : root["bufferViews"]) {
      const uint64_t b = view["buffer"].get<uint64_t>();
      if (b < renumbered.size()) view["buffer"] = renumbered[b];  // one past the list stays past it
    }
  buffers = std::move(kept);
}

// Accessors no mesh primitive reads (its attributes and indices; the tracer draws no morph
// targets) become empty SCALAR ones: a count of 1 without a buffer view.
void blank_unread_accessors(Json& root) {
  if (!root.contains("accessors")) return;
  std::set<uint64_t> read;
  if (root.contains("meshes"))
    for (const Json& mesh : root["meshes"])
      for (const Json& prim : mesh["primitives"]) {
        for (const auto& a : prim["attributes"].items()) read.insert(a.value().get<uint64_t>());
        if (prim.contains("indices")) read.insert(prim["indices"].get<uint64_t>());
      }
  Json& accessors = root["accessors"];
  for (size_t i = 0; i < accessors.size(); ++i)
    if (!read.count(i)) accessors[i] = {{"componentType", 5126}, {"count", 1}, {"type", "SCALAR"}};
}

// Gives every index accessor without a buffer view one (shared) over a new buffer of 4 zero bytes.
std::vector<int> give_index_accessors_a_view(Json& root) {
  std::vector<int> viewless;
  if (!root.contains("meshes")) return viewless;
  int64_t zeros = -1;  // the shared view
  for (const Json& mesh : root["meshes"])
    for (const Json& prim : mesh["primitives"]) {
      if (!prim.contains("indices")) continue;
      const uint64_t index = prim["indices"].get<uint64_t>();
      if (!root.contains("accessors") || index >= root["accessors"].size()) continue;  // named later
      Json& accessor = root["accessors"][index];
      if (accessor.contains("bufferView")) continue;
      if (zeros < 0) {
        if (!root.contains("buffers")) root["buffers"] = Json::array();
        if (!root.contains("bufferViews")) root["bufferViews"] = Json::array();
        root["buffers"].push_back({{"byteLength", 4}, {"uri", std::string(kBase64Prefix) + "AAAAAA=="}});
        root["bufferViews"].push_back({{"buffer", root["buffers"].size() - 1}, {"byteLength", 4}});
        zeros = static_cast<int64_t>(root["bufferViews"].size()) - 1;
      }
      accessor["bufferView"] = zeros;
      viewless.push_back(static_cast<int>(index));
    }
  return viewless;
}

}  // namespace

NormalizedGltf normalize_gltf_json(Json& root, bool binary, const std::string& file) {
  NormalizedGltf out;
  drop_extras(root);
  root.erase("animations");
  out.materials_in_file = root.contains("materials") ? root["materials"].size() : 0;
  out.material_in_file = drop_unused_materials(root);
  share_buffers_of_one_file(root);
  drop_unused_buffers(root, binary, file);
  blank_unread_accessors(root);
  for (const char* array : {"buffers", "images"}) {
    if (!root.contains(array)) continue;
    Json& list = root[array];
    for (size_t i = 0; i < list.size(); ++i) {
      if (!list[i].contains("uri")) continue;
      const std::string uri = list[i]["uri"].get<std::string>();
      if (uri.rfind("data:", 0) == 0) list[i]["uri"] = base64_data_uri(uri, file, at(array, i) + ".uri");
    }
  }
  out.viewless_index_accessors = give_index_accessors_a_view(root);
  return out;
}

std::string glb_with_json(const std::string& bytes, const std::string& json, const std::string& file) {
  uint32_t old_length;
  std::memcpy(&old_length, bytes.data() + 12, 4);
  const std::string rest = bytes.substr(20 + static_cast<size_t>(old_length));
  std::string chunk = json;
  while (chunk.size() % 4 != 0) chunk += ' ';
  const uint64_t total = 20 + uint64_t{chunk.size()} + rest.size();
  if (total > 0xffffffffull) throw InputError(file + ": more than 4 GiB once its JSON is rewritten");
  const uint32_t header[5] = {0x46546C67u, 2u, static_cast<uint32_t>(total), static_cast<uint32_t>(chunk.size()),
                              0x4E4F534Au};  // "glTF", version 2, length; the chunk's length and "JSON"
  std::string out(reinterpret_cast<const char*>(header), sizeof header);
  return out + chunk + rest;
}

}  // namespace tracer
