// Strict reading of a JSON scene: every value is read through a key path, so an error
// says where it is ("scene.json: shapes[3].radius: expected a number, got \"1\""), and
// every object is closed by finish(), which rejects keys nobody read.
#pragma once
#include <nlohmann/json_fwd.hpp>  // declarations only: the .cpp files that read values include json.hpp
#include <optional>
#include <set>
#include <string>

#include "io/input_error.h"
#include "kernel/base/vec3.h"

namespace tracer {

using Json = nlohmann::json;

// Parses text; malformed JSON becomes an InputError with line and column.
Json parse_json_text(const std::string& text, const std::string& file);

class JsonObject {
 public:
  JsonObject(const Json& value, std::string path, std::string file);
  const Json* find(const std::string& key);         // nullptr when absent; marks the key as read
  const Json& get(const std::string& key);          // error when absent
  std::string child(const std::string& key) const;  // "path.key"
  void finish() const;                              // error on any key not read
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  const std::string& path() const { return path_; }
  const std::string& file() const { return file_; }

  float number(const std::string& key);
  float number_or(const std::string& key, float fallback);
  uint64_t unsigned_integer(const std::string& key);
  uint32_t unsigned_integer_32(const std::string& key);  // error beyond 2^32 - 1, never truncated
  Vec3 vec3(const std::string& key);
  Vec3 vec3_or(const std::string& key, Vec3 fallback);
  Vec3 color(const std::string& key);  // non-negative RGB; textures are a later issue
  Vec3 color_or(const std::string& key, Vec3 fallback);
  std::string string(const std::string& key);
  std::string string_or(const std::string& key, const std::string& fallback);
  bool boolean_or(const std::string& key, bool fallback);

 private:
  const Json& value_;
  std::string path_;
  std::string file_;  // a copy: callers pass temporaries
  std::set<std::string> read_;
};

// Free-standing readers for values that are not object members (array items).
[[noreturn]] void fail_at(const std::string& file, const std::string& path, const std::string& message);
float read_number(const Json& v, const std::string& path, const std::string& file);
Vec3 read_vec3(const Json& v, const std::string& path, const std::string& file);
std::string describe(const Json& v);  // for "expected ..., got X" messages

}  // namespace tracer
