// One name table per enum the scene file, the command line and the manifests spell out:
// the names in the enum's order, used both to parse and to print. A name's enum value is
// its index (the enums number their values from 0 without gaps).
#pragma once
#include <algorithm>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "kernel/scene/scene_view.h"

namespace tracer {

template <class E>
struct EnumNames;  // kind: what the names name, for messages; names: in the enum's order

template <>
struct EnumNames<IntegratorKind> {
  static constexpr const char* kind = "integrator";
  static constexpr const char* names[] = {"whitted", "normals", "albedo", "depth", "path"};
};
template <>
struct EnumNames<SamplerKind> {
  static constexpr const char* kind = "sampler";
  static constexpr const char* names[] = {"center", "grid", "stochastic", "stratified", "sobol"};
};
template <>
struct EnumNames<AccelKind> {
  static constexpr const char* kind = "accel";
  static constexpr const char* names[] = {"bvh", "none", "kdtree", "kdtree-median", "grid", "lbvh"};
};
template <>
struct EnumNames<TriangleTest> {
  static constexpr const char* kind = "triangle test";
  static constexpr const char* names[] = {"watertight", "moller-trumbore"};
};
template <>
struct EnumNames<LightSampling> {
  static constexpr const char* kind = "light sampling";
  static constexpr const char* names[] = {"area", "solid-angle"};
};
template <>
struct EnumNames<Switch> {
  static constexpr const char* kind = "switch";
  static constexpr const char* names[] = {"off", "on"};
};
template <>
struct EnumNames<Schedule> {
  static constexpr const char* kind = "schedule";
  static constexpr const char* names[] = {"megakernel", "stream"};
};
template <>
struct EnumNames<StreamOrder> {
  static constexpr const char* kind = "stream order";
  static constexpr const char* names[] = {"queue", "sorted"};
};
template <>
struct EnumNames<BackgroundKind> {
  static constexpr const char* kind = "background";
#define TRACER_BACKGROUND_NAME(Kind, type) type,
  static constexpr const char* names[] = {TRACER_BACKGROUND_KINDS(TRACER_BACKGROUND_NAME)};
#undef TRACER_BACKGROUND_NAME
};
template <>
struct EnumNames<MaterialKind> {
  static constexpr const char* kind = "material";
#define TRACER_MATERIAL_NAME(Kind, Type, name, feature) name,
  static constexpr const char* names[] = {TRACER_MATERIAL_KINDS(TRACER_MATERIAL_NAME)};
#undef TRACER_MATERIAL_NAME
};
template <>
struct EnumNames<AlphaMode> {
  static constexpr const char* kind = "alpha mode";
  static constexpr const char* names[] = {"opaque", "mask", "blend"};
};
template <>
struct EnumNames<FresnelKind> {
  static constexpr const char* kind = "fresnel";
  static constexpr const char* names[] = {"schlick", "exact"};
};

// "a, b or c": for "expected ..." messages.
template <class List>
std::string name_list(const List& names) {
  std::string out;
  const size_t n = std::size(names);
  size_t i = 0;
  for (const auto& name : names) {
    if (i > 0) out += i + 1 == n ? " or " : ", ";
    out += name;
    ++i;
  }
  return out;
}

template <class E>
const char* enum_name(E value) {
  const auto index = static_cast<size_t>(value);
  return index < std::size(EnumNames<E>::names) ? EnumNames<E>::names[index] : "?";
}

template <class E>
std::optional<E> find_enum(const std::string& name) {
  for (size_t i = 0; i < std::size(EnumNames<E>::names); ++i)
    if (name == EnumNames<E>::names[i]) return static_cast<E>(i);
  return std::nullopt;
}

// InputError "WHERE: unknown integrator "x" (expected whitted, normals, ... or path)".
template <class E>
E parse_enum(const std::string& name, const std::string& where) {
  if (const std::optional<E> value = find_enum<E>(name)) return *value;
  throw InputError(where + ": unknown " + EnumNames<E>::kind + " \"" + name + "\" (expected " +
                   name_list(EnumNames<E>::names) + ")");
}

// The comma-separated names of `text` ("bvh,grid"), each read by parse_enum: none for an empty
// text; an empty name (",,", a comma at either end) is an unknown one.
template <class E>
std::vector<E> parse_enum_list(const std::string& text, const std::string& where) {
  std::vector<E> values;
  for (size_t start = 0; !text.empty() && start <= text.size();) {
    const size_t comma = std::min(text.find(',', start), text.size());
    values.push_back(parse_enum<E>(text.substr(start, comma - start), where));
    start = comma + 1;
  }
  return values;
}

}  // namespace tracer
