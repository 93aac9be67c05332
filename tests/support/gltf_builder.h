// glTF documents for tests: a valid one-triangle file (data-URI buffer, a camera, a material)
// as nlohmann JSON that a test edits before writing it, and the pieces to build others.
#pragma once
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace tracer::test {

inline std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t n = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) n |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) n |= static_cast<unsigned char>(bytes[i + 2]);
    out += digits[(n >> 18) & 63];
    out += digits[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? digits[n & 63] : '=';
  }
  return out;
}

template <class T>
std::string bytes_of(const std::vector<T>& values) {
  std::string s(values.size() * sizeof(T), '\0');
  std::memcpy(s.data(), values.data(), s.size());
  return s;
}

inline std::string data_uri(const std::string& bytes) {
  return "data:application/octet-stream;base64," + base64(bytes);
}

// One triangle at z = 0 facing a camera at z = 3 (a node translated there), material 0 a
// grey dielectric; buffer 0 holds the positions (36 bytes) then the indices 0, 1, 2 as
// unsigned shorts (6 bytes); accessor 0 the positions, 1 the indices.
inline nlohmann::json triangle_gltf() {
  const std::vector<float> positions = {-1, -1, 0, 1, -1, 0, 0, 1, 0};
  const std::vector<uint16_t> indices = {0, 1, 2};
  const std::string buffer = bytes_of(positions) + bytes_of(indices);
  return nlohmann::json::parse(R"({
    "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
    "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 0, 3]}],
    "cameras": [{"type": "perspective", "name": "cam", "perspective": {"yfov": 0.8, "aspectRatio": 2.0, "znear": 0.1}}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
    "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0, "roughnessFactor": 0.5}}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "min": [-1, -1, 0], "max": [1, 1, 0]},
                  {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
    "buffers": [{"byteLength": 42, "uri": ")" +
                               data_uri(buffer) + R"("}]})");
}

// A glTF document assembled piece by piece: accessors go into one binary buffer, written as a
// data URI by finish().
class GltfDoc {
 public:
  nlohmann::json doc = {
      {"asset", {{"version", "2.0"}}}, {"scene", 0}, {"scenes", {{{"nodes", nlohmann::json::array()}}}}};

  // A float accessor of `type` ("VEC2", "VEC3", "VEC4"); with bounds, its min and max per component.
  int floats(const std::vector<float>& values, const char* type, int components, bool bounds = false) {
    nlohmann::json a = {{"bufferView", view(bytes_of(values))},
                        {"componentType", 5126},
                        {"count", values.size() / components},
                        {"type", type}};
    if (bounds) {
      std::vector<float> lo(values.begin(), values.begin() + components), hi = lo;
      for (size_t i = 0; i < values.size(); ++i)
        lo[i % components] = std::min(lo[i % components], values[i]),
               hi[i % components] = std::max(hi[i % components], values[i]);
      a["min"] = lo;
      a["max"] = hi;
    }
    return push("accessors", a);
  }
  int indices(const std::vector<uint32_t>& values) {
    return push("accessors", {{"bufferView", view(bytes_of(values))},
                              {"componentType", 5125},
                              {"count", values.size()},
                              {"type", "SCALAR"}});
  }
  int push(const char* array, const nlohmann::json& element) {
    doc[array].push_back(element);
    return static_cast<int>(doc[array].size()) - 1;
  }
  nlohmann::json finish() const {
    nlohmann::json out = doc;
    out["buffers"] = {{{"byteLength", bin_.size()}, {"uri", data_uri(bin_)}}};
    return out;
  }

 private:
  int view(const std::string& bytes) {
    while (bin_.size() % 4 != 0) bin_ += '\0';
    const int v = push("bufferViews", {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", bytes.size()}});
    bin_ += bytes;
    return v;
  }
  std::string bin_;
};

// A .glb of `doc` (its first buffer the binary chunk `bin`; glTF 2.0, 4.4).
inline std::string write_glb(const std::filesystem::path& path, const nlohmann::json& doc, std::string bin) {
  std::string json = doc.dump();
  while (json.size() % 4 != 0) json += ' ';
  while (bin.size() % 4 != 0) bin += '\0';
  const uint32_t header[5] = {0x46546C67u, 2u, static_cast<uint32_t>(28 + json.size() + bin.size()),
                              static_cast<uint32_t>(json.size()), 0x4E4F534Au};
  const uint32_t bin_header[2] = {static_cast<uint32_t>(bin.size()), 0x004E4942u};
  std::ofstream(path, std::ios::binary) << std::string(reinterpret_cast<const char*>(header), sizeof header) << json
                                        << std::string(reinterpret_cast<const char*>(bin_header), sizeof bin_header)
                                        << bin;
  return path.string();
}

inline std::string write_gltf(const std::filesystem::path& path, const nlohmann::json& doc) {
  std::ofstream(path, std::ios::binary) << doc.dump();
  return path.string();
}

}  // namespace tracer::test
