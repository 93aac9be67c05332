#include "options/render_options.h"

#include <limits>
#include <nlohmann/json.hpp>
#include <type_traits>

#include "kernel/light/environment_light.h"
#include "options/effects.h"
#include "options/enum_names.h"
#include "options/number_text.h"
#include "options/settings_check.h"

namespace tracer {
namespace {

// An option's value from its JSON form (scene file, manifest, partial file): numbers for
// counts and seeds, true/false for switches, names for enums and effects.
template <class T>
T value_from_json(const Json& v, const std::string& path, const std::string& file) {
  const std::string where = file + ": " + path;
  if constexpr (std::is_same_v<T, uint32_t> || std::is_same_v<T, uint64_t>) {
    if (!v.is_number_integer() || (!v.is_number_unsigned() && v.get<int64_t>() < 0) ||
        v.get<uint64_t>() > std::numeric_limits<T>::max())
      fail_at(file, path, "expected " + count_range(0, std::numeric_limits<T>::max()) + ", got " + describe(v));
    return static_cast<T>(v.get<uint64_t>());
  } else if constexpr (std::is_same_v<T, float>) {  // thresholds: positive and finite
    if (!v.is_number() || !(v.get<double>() >= kThresholdMin) || !(v.get<double>() <= kThresholdMax))
      fail_at(file, path,
              "expected a number from 1.2e-38 (a float's smallest normal number) to 1e6, got " + describe(v));
    return static_cast<float>(v.get<double>());
  } else if constexpr (std::is_same_v<T, Switch>) {
    if (!v.is_boolean()) fail_at(file, path, "expected true or false, got " + describe(v));
    return v.get<bool>() ? Switch::On : Switch::Off;
  } else {
    if (!v.is_string()) fail_at(file, path, "expected a string, got " + describe(v));
    if constexpr (std::is_same_v<T, Effects>)
      return parse_effects(v.get<std::string>(), where);
    else
      return parse_enum<T>(v.get<std::string>(), where);
  }
}

template <class T>
nlohmann::ordered_json value_to_json(T value) {
  if constexpr (std::is_same_v<T, uint32_t> || std::is_same_v<T, uint64_t>)
    return value;
  else if constexpr (std::is_same_v<T, float>)
    return shortest_decimal(value);
  else if constexpr (std::is_same_v<T, Switch>)
    return value == Switch::On;
  else if constexpr (std::is_same_v<T, Effects>)
    return effects_text(value);
  else
    return enum_name(value);
}

// Command-line text: decimal digits only (no sign, space or empty string), on/off, names.
template <class T>
T value_from_text(const std::string& text, const std::string& flag) {
  if constexpr (std::is_same_v<T, uint32_t> || std::is_same_v<T, uint64_t>) {
    const std::optional<uint64_t> value = parse_count(text, std::numeric_limits<T>::max());
    if (!value) throw InputError(flag + " \"" + text + "\": expected " + count_range(0, std::numeric_limits<T>::max()));
    return static_cast<T>(*value);
  } else if constexpr (std::is_same_v<T, float>) {
    const std::optional<double> value = parse_decimal(text, 0.0, kThresholdMax);
    if (!value || !(*value >= kThresholdMin))
      throw InputError(flag + " \"" + text +
                       "\": expected a decimal number from 1.2e-38 (a float's smallest normal number) to 1e6");
    return static_cast<float>(*value);
  } else if constexpr (std::is_same_v<T, Effects>) {
    return parse_effects(text, flag);
  } else {
    return parse_enum<T>(text, flag);
  }
}

}  // namespace

const std::vector<OptionInfo>& option_table() {
  static const std::vector<OptionInfo> table = {
#define TRACER_OPTION_INFO(name, Type, default_value, section, recorded, help) \
  {#name, #section, Record::recorded, help},
      TRACER_RENDER_OPTIONS(TRACER_OPTION_INFO)
#undef TRACER_OPTION_INFO
  };
  return table;
}

std::string option_flag(const std::string& name) {
  std::string flag = "--" + name;
  for (char& c : flag)
    if (c == '_') c = '-';
  return flag;
}

bool RenderOptions::complete() const {
#define TRACER_OPTION_COMPLETE(name, Type, default_value, section, recorded, help) \
  if (Record::recorded == Record::Always && !name) return false;
  TRACER_RENDER_OPTIONS(TRACER_OPTION_COMPLETE)
#undef TRACER_OPTION_COMPLETE
  return true;
}

bool RenderOptions::has(const std::string& key) const {
#define TRACER_OPTION_HAS(name, ...) \
  if (key == #name) return name.has_value();
  TRACER_RENDER_OPTIONS(TRACER_OPTION_HAS)
#undef TRACER_OPTION_HAS
  return false;
}

void RenderOptions::apply_to(RenderSettings& settings) const {
#define TRACER_OPTION_APPLY(name, ...) \
  if (name) settings.name = *name;
  TRACER_RENDER_OPTIONS(TRACER_OPTION_APPLY)
#undef TRACER_OPTION_APPLY
}

void RenderOptions::override_with(const RenderOptions& other) {
#define TRACER_OPTION_OVERRIDE(name, ...) \
  if (other.name) name = other.name;
  TRACER_RENDER_OPTIONS(TRACER_OPTION_OVERRIDE)
#undef TRACER_OPTION_OVERRIDE
}

nlohmann::ordered_json RenderOptions::to_json() const {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
#define TRACER_OPTION_TO_JSON(name, ...) \
  if (name) j[#name] = value_to_json(*name);
  TRACER_RENDER_OPTIONS(TRACER_OPTION_TO_JSON)
#undef TRACER_OPTION_TO_JSON
  return j;
}

void read_options(JsonObject& obj, const char* section, RenderOptions& into) {
  const std::string wanted = section ? section : "";
#define TRACER_OPTION_READ(name, Type, default_value, option_section, recorded, help) \
  if (wanted.empty() || wanted == #option_section)                                    \
    if (const Json* v = obj.find(#name)) into.name = value_from_json<Type>(*v, obj.child(#name), obj.file());
  TRACER_RENDER_OPTIONS(TRACER_OPTION_READ)
#undef TRACER_OPTION_READ
}

void parse_option_text(const std::string& key, const std::string& text, const std::string& context,
                       RenderOptions& into) {
#define TRACER_OPTION_TEXT(name, Type, ...)                                \
  if (key == #name) {                                                      \
    into.name = value_from_text<Type>(text, context + option_flag(#name)); \
    return;                                                                \
  }
  TRACER_RENDER_OPTIONS(TRACER_OPTION_TEXT)
#undef TRACER_OPTION_TEXT
  throw InputError(context + "unknown render option \"" + key + "\"");
}

RenderOptions resolved_options(const RenderSettings& settings) {
  RenderOptions o;
#define TRACER_OPTION_RESOLVED(name, ...) o.name = settings.name;
  TRACER_RENDER_OPTIONS(TRACER_OPTION_RESOLVED)
#undef TRACER_OPTION_RESOLVED
  return o;
}

RenderOptions recorded_options(const RenderSettings& settings, BackgroundKind background) {
  const RenderSettings defaults{};
  const bool path = settings.integrator == IntegratorKind::Path;
  const auto records = [&](Record rule, bool at_default) {
    switch (rule) {
      case Record::Always: return true;
      case Record::PathTracer: return path;
      case Record::PathTracerUnderEnvironmentLight: return path && samples_environment(background);
      case Record::UnlessDefault: return !at_default;
      case Record::Never: return false;
    }
    return true;
  };
  RenderOptions o;
#define TRACER_OPTION_RECORDED(name, Type, default_value, section, recorded, help) \
  if (records(Record::recorded, settings.name == defaults.name)) o.name = settings.name;
  TRACER_RENDER_OPTIONS(TRACER_OPTION_RECORDED)
#undef TRACER_OPTION_RECORDED
  return o;
}

}  // namespace tracer
