// The container of a scene bundle and of a GPU parity case: named arrays of fixed-size
// elements in one versioned binary file with a SHA-1 checksum. Layout (little-endian):
//   "TRBUNDLE", u32 version, u32 kind length, kind, u32 section count,
//   per section: u32 name length, name, u32 element size, u64 element count, the bytes;
//   then the SHA-1 of everything before it (20 bytes).
// Standard library only: the self-contained GPU runner (cuda/runner/) reads it.
#pragma once
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "io/input_error.h"

namespace tracer {

// 2: TriangleShading gained bitangent_sign; 3: Light gained its kind; 4: its direction, cone and disc.
// 6: SceneView's environment cells by columns and rows; Background's equirectangular map.
// 7: Material gained its cut-out (alpha_mode, alpha, alpha_cutoff, alpha_map).
// 8: Texture gained times and plus (a use's factor, applied after filtering).
constexpr uint32_t kBundleVersion = 9;
constexpr uint64_t kBundleMaxBytes = 1ull << 30;  // what a reader accepts

struct BundleSection {
  std::string name;
  uint32_t element_size = 0;
  std::string bytes;  // element_size x count bytes
};

struct BundleFile {
  std::string kind;  // "scene" or "parity"
  std::vector<BundleSection> sections;

  template <class T>
  void add(const std::string& name, const std::vector<T>& values) {
    BundleSection s{name, static_cast<uint32_t>(sizeof(T)), std::string(values.size() * sizeof(T), '\0')};
    if (!values.empty()) std::memcpy(s.bytes.data(), values.data(), s.bytes.size());
    sections.push_back(std::move(s));
  }
  template <class T>
  void add_one(const std::string& name, const T& value) {
    add(name, std::vector<T>{value});
  }

  // The section's elements; InputError naming `file` and the section when it is missing or
  // its element size is not sizeof(T) (a bundle from a build with another layout).
  template <class T>
  std::vector<T> get(const std::string& name, const std::string& file) const {
    const BundleSection& s = find(name, file);
    if (s.element_size != sizeof(T))
      throw InputError(file + ": section " + name + " has elements of " + std::to_string(s.element_size) +
                       " bytes; this build's are " + std::to_string(sizeof(T)) + " (written by another version?)");
    std::vector<T> values(s.bytes.size() / sizeof(T));
    if (!values.empty()) std::memcpy(values.data(), s.bytes.data(), s.bytes.size());
    return values;
  }
  template <class T>
  T get_one(const std::string& name, const std::string& file) const {
    const std::vector<T> v = get<T>(name, file);
    if (v.size() != 1)
      throw InputError(file + ": section " + name + " should hold one element, holds " + std::to_string(v.size()));
    return v[0];
  }
  bool has(const std::string& name) const;
  const BundleSection& find(const std::string& name, const std::string& file) const;
};

std::string encode_bundle(const BundleFile& bundle);
void write_bundle(const std::string& path, const BundleFile& bundle);  // atomically; InputError when it cannot
// InputError naming the file: not a regular file, too large, truncated, a checksum that
// does not match, a wrong magic, version or kind, sections that run past the end.
BundleFile read_bundle(const std::string& path, const std::string& expected_kind);
BundleFile decode_bundle(const std::string& bytes, const std::string& path, const std::string& expected_kind);

}  // namespace tracer
