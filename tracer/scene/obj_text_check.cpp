#include "scene/obj_text_check.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "io/input_error.h"

namespace tracer {
namespace {

bool finite_number(const std::string& token) {
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size() && !token.empty() && errno == 0 && std::isfinite(v) &&
         std::isfinite(static_cast<float>(v));
}

// A face index: an optional '-' and digits, not 0, within 32 bits.
bool face_index(const std::string& token) {
  if (token.empty() || token.size() > 11) return false;
  const size_t digits = token[0] == '-' ? 1 : 0;
  if (digits == token.size()) return false;
  for (size_t i = digits; i < token.size(); ++i)
    if (token[i] < '0' || token[i] > '9') return false;
  const long long v = std::stoll(token);
  return v != 0 && v >= -2147483647ll && v <= 2147483647ll;
}

bool face_reference(const std::string& ref) {
  std::vector<std::string> parts;
  std::string part;
  std::stringstream in(ref);
  while (std::getline(in, part, '/')) parts.push_back(part);
  if (!ref.empty() && ref.back() == '/') parts.push_back("");
  if (parts.empty() || parts.size() > 3 || !face_index(parts[0])) return false;
  for (size_t i = 1; i < parts.size(); ++i)
    if (!parts[i].empty() && !face_index(parts[i])) return false;
  return parts.size() != 2 || !parts[1].empty();  // "i/" is not a reference
}

}  // namespace

void check_obj_text(const std::string& text, const std::string& where) {
  std::stringstream lines(text);
  std::string line;
  for (size_t number = 1; std::getline(lines, line); ++number) {
    std::stringstream words(line);
    std::string keyword, word;
    words >> keyword;
    std::vector<std::string> args;
    while (words >> word) args.push_back(word);
    const auto fail = [&](const std::string& message) {
      throw InputError(where + ": line " + std::to_string(number) + ": " + message);
    };
    const auto numbers = [&](std::initializer_list<size_t> counts, const char* what) {
      bool count_ok = false;
      for (size_t c : counts) count_ok = count_ok || args.size() == c;
      if (!count_ok) fail(std::string(what) + ": wrong number of values (" + std::to_string(args.size()) + ")");
      for (const std::string& a : args)
        if (!finite_number(a)) fail(std::string(what) + ": \"" + a.substr(0, 40) + "\" is not a finite number");
    };
    if (keyword == "v")
      numbers({3, 4, 6}, "vertex (v)");
    else if (keyword == "vn")
      numbers({3}, "normal (vn)");
    else if (keyword == "vt")
      numbers({2, 3}, "texture coordinate (vt)");
    else if (keyword == "f") {
      if (args.size() < 3) fail("face (f) with " + std::to_string(args.size()) + " vertices; a face needs at least 3");
      for (const std::string& a : args)
        if (!face_reference(a))
          fail("face (f): \"" + a.substr(0, 40) + "\" is not i, i/j, i//k or i/j/k with whole non-zero indices");
    }
  }
}

}  // namespace tracer
