#include "io/json_reader.h"

#include <cmath>
#include <set>
#include <vector>

namespace tracer {

namespace {

// Deeper values are refused while parsing, so that printing or destroying one never
// recurses far (nlohmann's dump recurses once per level).
constexpr int kMaxJsonDepth = 64;

// A key as error messages print it: at most 60 characters.
std::string shown_key(const std::string& key) { return key.size() > 60 ? key.substr(0, 57) + "..." : key; }

}  // namespace

Json parse_json_text(const std::string& text, const std::string& file) {
  // Per open object, the keys seen so far and the last one (for the path in a message).
  struct OpenObject {
    std::set<std::string> keys;
    std::string last;
  };
  std::vector<OpenObject> objects;
  const Json::parser_callback_t check = [&](int depth, Json::parse_event_t event, Json& parsed) {
    if (depth > kMaxJsonDepth)
      throw InputError(file + ": JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    if (event == Json::parse_event_t::object_start) objects.emplace_back();
    if (event == Json::parse_event_t::object_end && !objects.empty()) objects.pop_back();
    if (event == Json::parse_event_t::key && !objects.empty()) {
      const std::string key = parsed.get<std::string>();
      if (!objects.back().keys.insert(key).second) {
        std::string path;
        for (size_t i = 0; i + 1 < objects.size(); ++i) path += objects[i].last + ".";
        throw InputError(file + ": key " + shown_key(path + key) + " appears twice in one object");
      }
      objects.back().last = key;
    }
    return true;
  };
  try {
    return Json::parse(text, check);
  } catch (const Json::parse_error& e) {
    // nlohmann reports a byte offset; turn it into line:column.
    size_t line = 1, column = 1;
    const size_t end = std::min<size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
    for (size_t i = 0; i < end; ++i) {
      if (text[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    std::string what = e.what();
    const size_t colon = what.find("parse error");
    if (colon != std::string::npos) what = what.substr(colon);
    throw InputError(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": malformed JSON: " + what);
  } catch (const Json::out_of_range& e) {  // e.g. 1e999: no position is reported
    throw InputError(file + ": malformed JSON: " + e.what());
  }
}

std::string describe(const Json& v) {
  std::string s = v.dump();
  if (s.size() > 40) s = s.substr(0, 37) + "...";
  return s;
}

void fail_at(const std::string& file, const std::string& path, const std::string& message) {
  throw InputError(file + ": " + path + ": " + message);
}

float read_number(const Json& v, const std::string& path, const std::string& file) {
  if (!v.is_number()) fail_at(file, path, "expected a number, got " + describe(v));
  const double d = v.get<double>();
  const float f = static_cast<float>(d);
  if (!std::isfinite(d) || !std::isfinite(f)) fail_at(file, path, "expected a finite number, got " + describe(v));
  return f;
}

Vec3 read_vec3(const Json& v, const std::string& path, const std::string& file) {
  if (!v.is_array() || v.size() != 3) fail_at(file, path, "expected an array of 3 numbers, got " + describe(v));
  return {read_number(v[0], path + "[0]", file), read_number(v[1], path + "[1]", file),
          read_number(v[2], path + "[2]", file)};
}

JsonObject::JsonObject(const Json& value, std::string path, std::string file)
    : value_(value), path_(std::move(path)), file_(std::move(file)) {
  if (!value_.is_object())
    fail_at(file_, path_.empty() ? "(top level)" : path_, "expected an object, got " + describe(value_));
}

std::string JsonObject::child(const std::string& key) const {
  return path_.empty() ? shown_key(key) : path_ + "." + shown_key(key);
}

void JsonObject::fail(const std::string& key, const std::string& message) const {
  fail_at(file_, key.empty() ? path_ : child(key), message);
}

const Json* JsonObject::find(const std::string& key) {
  read_.insert(key);
  const auto it = value_.find(key);
  return it == value_.end() ? nullptr : &*it;
}

const Json& JsonObject::get(const std::string& key) {
  const Json* v = find(key);
  if (!v) fail(key, "missing required key");
  return *v;
}

void JsonObject::finish() const {
  for (const auto& item : value_.items())
    if (!read_.count(item.key())) fail(item.key(), "unknown key");
}

float JsonObject::number(const std::string& key) { return read_number(get(key), child(key), file_); }

float JsonObject::number_or(const std::string& key, float fallback) {
  const Json* v = find(key);
  return v ? read_number(*v, child(key), file_) : fallback;
}

uint64_t JsonObject::unsigned_integer(const std::string& key) {
  const Json& v = get(key);
  if (!v.is_number_integer() || (v.is_number_integer() && !v.is_number_unsigned() && v.get<int64_t>() < 0))
    fail(key, "expected a non-negative integer, got " + describe(v));
  return v.get<uint64_t>();
}

Vec3 JsonObject::vec3(const std::string& key) { return read_vec3(get(key), child(key), file_); }

Vec3 JsonObject::vec3_or(const std::string& key, Vec3 fallback) {
  const Json* v = find(key);
  return v ? read_vec3(*v, child(key), file_) : fallback;
}

Vec3 JsonObject::color(const std::string& key) {
  const Json& v = get(key);
  if (v.is_object() && (v.contains("texture") || v.contains("checker")))
    fail(key, "a texture or checker can replace a material's colour only; this colour must be [r, g, b]");
  const Vec3 c = read_vec3(v, child(key), file_);
  if (c.x < 0.0f || c.y < 0.0f || c.z < 0.0f) fail(key, "colour components must be >= 0");
  return c;
}

Vec3 JsonObject::color_or(const std::string& key, Vec3 fallback) {
  return value_.contains(key) ? color(key) : (read_.insert(key), fallback);
}

std::string JsonObject::string(const std::string& key) {
  const Json& v = get(key);
  if (!v.is_string()) fail(key, "expected a string, got " + describe(v));
  return v.get<std::string>();
}

std::string JsonObject::string_or(const std::string& key, const std::string& fallback) {
  return value_.contains(key) ? string(key) : (read_.insert(key), fallback);
}

bool JsonObject::boolean_or(const std::string& key, bool fallback) {
  const Json* v = find(key);
  if (!v) return fallback;
  if (!v->is_boolean()) fail(key, "expected true or false, got " + describe(*v));
  return v->get<bool>();
}

}  // namespace tracer
