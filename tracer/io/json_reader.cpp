#include "io/json_reader.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <vector>

namespace tracer {

namespace {

// Deeper values are refused while parsing, so that printing or destroying one never
// recurses far (nlohmann's dump recurses once per level).
constexpr int kMaxJsonDepth = 64;

// A key as error messages print it: at most 60 characters.
std::string shown_key(const std::string& key) { return key.size() > 60 ? key.substr(0, 57) + "..." : key; }

// nlohmann's DOM builder behind a SAX filter that refuses what the format does not: nesting
// deeper than kMaxJsonDepth (refused while parsing, before anything recurses) and a key twice
// in one object (nlohmann would keep the last silently). A filter, not nlohmann's parser
// callback: that one rescans the enclosing array after every object it ends, which made an
// array of n objects take time n^2 (400,000 spheres: 37 s).
class CheckedJsonBuilder {
 public:
  CheckedJsonBuilder(Json& result, const std::string& file) : dom_(result), file_(file) {}
  bool null() { return value() && dom_.null(); }
  bool boolean(bool v) { return value() && dom_.boolean(v); }
  bool number_integer(Json::number_integer_t v) { return value() && dom_.number_integer(v); }
  bool number_unsigned(Json::number_unsigned_t v) { return value() && dom_.number_unsigned(v); }
  bool number_float(Json::number_float_t v, const std::string& s) { return value() && dom_.number_float(v, s); }
  bool string(std::string& v) { return value() && dom_.string(v); }
  bool binary(Json::binary_t& v) { return value() && dom_.binary(v); }
  bool start_object(std::size_t n) {
    open();
    objects_.emplace_back();
    return dom_.start_object(n);
  }
  bool key(std::string& k) {
    OpenObject& o = objects_.back();
    if (!o.keys.insert(k).second) {
      std::string path;
      for (size_t i = 0; i + 1 < objects_.size(); ++i) path += objects_[i].last + ".";
      throw InputError(file_ + ": key " + shown_key(path + k) + " appears twice in one object");
    }
    o.last = k;
    return dom_.key(k);
  }
  bool end_object() {
    objects_.pop_back();
    --depth_;
    return dom_.end_object();
  }
  bool start_array(std::size_t n) {
    open();
    return dom_.start_array(n);
  }
  bool end_array() {
    --depth_;
    return dom_.end_array();
  }
  template <class Exception>  // the concrete type (parse_error, out_of_range), thrown as such
  bool parse_error(std::size_t position, const std::string& token, const Exception& e) {
    return dom_.parse_error(position, token, e);  // throws the parse_error, with its byte offset
  }

 private:
  struct OpenObject {
    std::set<std::string> keys;
    std::string last;  // for the key path in a message
  };
  // An element inside more than kMaxJsonDepth containers is refused.
  bool value() {
    if (depth_ > kMaxJsonDepth) too_deep();
    return true;
  }
  void open() {
    value();
    ++depth_;
  }
  [[noreturn]] void too_deep() const {
    throw InputError(file_ + ": JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
  }
  nlohmann::detail::json_sax_dom_parser<Json> dom_;
  const std::string& file_;
  std::vector<OpenObject> objects_;
  int depth_ = 0;
};

// "LINE:COLUMN" of byte `offset` of `text`.
std::string line_column(const std::string& text, size_t offset) {
  size_t line = 1, column = 1;
  for (size_t i = 0; i < std::min(offset, text.size()); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

}  // namespace

Json parse_json_text(const std::string& text, const std::string& file) {
  Json result;
  CheckedJsonBuilder builder(result, file);
  try {
    Json::sax_parse(text, &builder);
    return result;
  } catch (const Json::parse_error& e) {
    // nlohmann reports a byte offset; turn it into line:column.
    std::string what = e.what();
    const size_t colon = what.find("parse error");
    if (colon != std::string::npos) what = what.substr(colon);
    throw InputError(file + ":" + line_column(text, e.byte > 0 ? e.byte - 1 : 0) + ": malformed JSON: " + what);
  } catch (const Json::out_of_range& e) {
    // A number beyond a double (1e400): nlohmann names the token ("number overflow parsing
    // '1e400'"), not where it is; its first occurrence in the text is the place.
    const std::string what = e.what();
    const size_t open = what.find('\''), close = what.rfind('\'');
    const std::string token = open != std::string::npos && close > open ? what.substr(open + 1, close - open - 1) : "";
    const size_t at = token.empty() ? std::string::npos : text.find(token);
    throw InputError(file + (at == std::string::npos ? "" : ":" + line_column(text, at)) +
                     ": malformed JSON: the number " + (token.empty() ? std::string("") : token + " ") +
                     "is beyond the range of a double (about 1.8e308)");
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

uint32_t JsonObject::unsigned_integer_32(const std::string& key) {
  const uint64_t v = unsigned_integer(key);
  if (v > UINT32_MAX) fail(key, "must fit in 32 bits, got " + std::to_string(v));
  return static_cast<uint32_t>(v);
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
