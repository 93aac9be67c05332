// The host side of the options table (TRACER_RENDER_OPTIONS in kernel/scene/render_settings.h):
// every setting read from the scene file's `render` and `film` keys, overridden by the
// command line, recorded in a golden's manifest entry and in a partial file's identity, and
// reported by --stats, all by looping over that one list.
#pragma once
#include <nlohmann/json_fwd.hpp>  // declarations only: the .cpp files that read values include json.hpp
#include <optional>
#include <string>
#include <vector>

#include "io/json_reader.h"
#include "kernel/material/material.h"
#include "kernel/scene/render_settings.h"
#include "kernel/scene/scene_view.h"

namespace tracer {

// When an identity (manifest entry, partial file) records an option: it decides the pixels.
// Never: it decides only how they are computed (the schedule), so partials merge across it.
enum class Record { Always, PathTracer, PathTracerUnderEnvironmentLight, UnlessDefault, Never };

// One row of the table, for loops that need no value: the CLI's flags, docs, messages.
struct OptionInfo {
  const char* name;     // field, scene key and manifest key: "max_depth"
  const char* section;  // the scene file's object holding it: "render" or "film"
  Record recorded;
  const char* help;
};
const std::vector<OptionInfo>& option_table();
std::string option_flag(const std::string& name);  // "--max-depth"

// Every option, each unset unless given.
struct RenderOptions {
#define TRACER_OPTION_FIELD(name, Type, ...) std::optional<Type> name;
  TRACER_RENDER_OPTIONS(TRACER_OPTION_FIELD)
#undef TRACER_OPTION_FIELD

  bool complete() const;                           // every option recorded Always is set
  bool has(const std::string& name) const;         // the option of that name is set
  void apply_to(RenderSettings& settings) const;   // the set options replace the settings' values
  void override_with(const RenderOptions& other);  // the options set in `other` replace these
  nlohmann::ordered_json to_json() const;          // the set options in table order
};

// Command-line overrides of a scene: the options, and the Fresnel model of every dielectric
// (a `bench trade` knob, not an option of the renderer).
struct RenderOverrides : RenderOptions {
  RenderOverrides() = default;
  explicit RenderOverrides(const RenderOptions& options) : RenderOptions(options) {}
  std::optional<FresnelKind> fresnel;
  // glTF files only (docs/gltf.md): the camera, by name or index, and a constant background.
  std::optional<std::string> camera;
  std::optional<Vec3> background;
  // Any scene: an equirectangular image (a path) replacing its background.
  std::optional<std::string> environment;
  // Where the options come from, for messages: empty for the command line, else the file and
  // key path that set them ("golden/manifest.json: goldens.ball.options").
  std::string origin;
};

// Reads the options of `section` ("render", "film"; nullptr: every option) present in obj;
// errors name the file and key.
void read_options(JsonObject& obj, const char* section, RenderOptions& into);

// Sets the option `name` from command-line text; an InputError names `context` (the scene
// file and "command line ") and the flag, or the unknown name. Numbers are decimal digits only; switches are on or off.
void parse_option_text(const std::string& name, const std::string& text, const std::string& context,
                       RenderOptions& into);

// Every option of resolved settings, and those of them an identity records (the background
// decides whether sky sampling matters).
RenderOptions resolved_options(const RenderSettings& settings);
RenderOptions recorded_options(const RenderSettings& settings, BackgroundKind background);

}  // namespace tracer
