// glTF documents for tests: a valid one-triangle file (data-URI buffer, a camera, a material)
// as nlohmann JSON that a test edits before writing it, and the pieces to build others.
#pragma once
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

inline std::string write_gltf(const std::filesystem::path& path, const nlohmann::json& doc) {
  std::ofstream(path, std::ios::binary) << doc.dump();
  return path.string();
}

}  // namespace tracer::test
