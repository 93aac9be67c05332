// The options table (kernel/scene/render_settings.h): every option reaches the command line,
// the scene file, the manifest/identity JSON and --stats by looping over the one list, and
// each is parsed strictly on every path.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "options/enum_names.h"
#include "options/render_options.h"
#include "test_util.h"

namespace tracer {
namespace {

constexpr const char* kScene =
    R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 3], "to": [0, 0, 0], "vfov": 40},
  "film": {"width": 4, "height": 4}, RENDER "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}},
  "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})";

std::string scene_with(const std::string& render) {
  std::string s = kScene;
  s.replace(s.find("RENDER"), 6, render.empty() ? "" : "\"render\": " + render + ",");
  return s;
}

// Options set away from their defaults, one value per option, given as JSON.
nlohmann::json changed_options() {
  return {{"integrator", "path"},
          {"sampler", "stochastic"},
          {"spp", 4},
          {"seed", 9},
          {"width", 6},
          {"height", 5},
          {"accel", "kdtree"},
          {"max_depth", 7},
          {"nee", false},
          {"rr_depth", 2},
          {"sky_sampling", false},
          {"light_sampling", "solid-angle"},
          {"mirror_images", false},
          {"triangle_test", "moller-trumbore"},
          {"grid_resolution", 12},
          {"effects", "shadows,reflections"},
          {"noise_threshold", 0.25},  // exact in float, so the JSON round trip is exact
          {"min_spp", 2},
          {"target_error", 0.5},
          {"schedule", "stream"},
          {"stream_width", 1000},
          {"stream_order", "sorted"}};
}

TEST(RenderOptions, EveryOptionIsCoveredByThisTest) {
  for (const OptionInfo& o : option_table()) EXPECT_TRUE(changed_options().contains(o.name)) << o.name;
  EXPECT_EQ(changed_options().size(), option_table().size());
}

// The JSON form round-trips: read_options(to_json(x)) == x, for every option.
TEST(RenderOptions, JsonRoundTrip) {
  const nlohmann::json j = changed_options();
  RenderOptions o;
  JsonObject obj(j, "options", "manifest.json");
  read_options(obj, nullptr, o);
  obj.finish();
  EXPECT_TRUE(o.complete());
  EXPECT_EQ(nlohmann::json::parse(o.to_json().dump()), j);
}

// A scene file's `render` and `film` keys set every option, and the resolved settings hold them.
TEST(RenderOptions, SceneFileSetsEveryOption) {
  nlohmann::json render = nlohmann::json::object();
  nlohmann::json film = nlohmann::json::object();
  for (const OptionInfo& o : option_table())
    (std::string(o.section) == "film" ? film : render)[o.name] = changed_options()[o.name];
  std::string text = scene_with(render.dump());
  text.replace(text.find(R"({"width": 4, "height": 4})"), 25, film.dump());
  const Scene scene = test::scene_from(text);
  EXPECT_EQ(nlohmann::json::parse(resolved_options(scene.settings).to_json().dump()), changed_options());
}

// The command line reaches every option: its flag is in `render --help`, and a render given
// every flag reports each value in --stats.
TEST(RenderOptions, CommandLineSetsEveryOption) {
  std::string help;
  ASSERT_EQ(test::run_tracer("render --help", &help), 0);
  std::string args;
  for (const OptionInfo& o : option_table()) {
    EXPECT_NE(help.find(option_flag(o.name)), std::string::npos) << o.name;
    const nlohmann::json v = changed_options()[o.name];
    args += " " + option_flag(o.name) + " " +
            (v.is_boolean()  ? (v.get<bool>() ? "on" : "off")
             : v.is_string() ? v.get<std::string>()
                             : v.dump());
  }
  const auto dir = test::temp_dir("options-cli");
  std::ofstream(dir / "s.json") << scene_with("");
  std::string output;
  ASSERT_EQ(test::run_tracer("render " + (dir / "s.json").string() + args + " --quiet -o " + (dir / "s.exr").string() +
                                 " --stats " + (dir / "stats.json").string(),
                             &output),
            0)
      << output;
  std::ifstream stats(dir / "stats.json");
  EXPECT_EQ(nlohmann::json::parse(stats)["options"], changed_options());
  std::filesystem::remove_all(dir);
}

// An identity records what decides the pixels: the eight core options always, the path
// tracer's only for it, the rest when they differ from their defaults.
TEST(RenderOptions, RecordedWhenTheyDecideThePixels) {
  RenderSettings whitted{};
  RenderOptions w = recorded_options(whitted, BackgroundKind::Constant);
  EXPECT_TRUE(w.complete());
  EXPECT_FALSE(w.nee || w.rr_depth || w.sky_sampling || w.light_sampling || w.triangle_test || w.grid_resolution ||
               w.effects);
  RenderSettings path{};
  path.integrator = IntegratorKind::Path;
  path.grid_resolution = 8;
  RenderOptions p = recorded_options(path, BackgroundKind::Constant);
  EXPECT_TRUE(p.nee && p.rr_depth && p.grid_resolution);
  EXPECT_FALSE(p.sky_sampling);
  EXPECT_TRUE(recorded_options(path, BackgroundKind::Cubemap).sky_sampling);
  path.schedule = Schedule::Stream;  // how the pixels are computed, not what they are
  path.stream_width = 7;
  path.stream_order = StreamOrder::Sorted;
  const RenderOptions s = recorded_options(path, BackgroundKind::Constant);
  EXPECT_FALSE(s.schedule || s.stream_width || s.stream_order);
}

// Command-line numbers are decimal digits that fit; anything else names the flag.
TEST(RenderOptions, CommandLineNumbersAreStrict) {
  for (const std::string bad : {"", " 4", "4 ", "-1", "+4", "0x10", "4.0", "4294967296", "99999999999999999999999"}) {
    RenderOptions o;
    try {
      parse_option_text("spp", bad, "s.json: command line ", o);
      ADD_FAILURE() << "accepted \"" << bad << "\"";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("s.json: command line --spp"), std::string::npos) << e.what();
    }
  }
  RenderOptions o;
  parse_option_text("spp", "4294967295", "", o);
  EXPECT_EQ(*o.spp, 4294967295u);
  parse_option_text("seed", "18446744073709551615", "", o);
  EXPECT_EQ(*o.seed, 18446744073709551615ull);
  EXPECT_THROW(parse_option_text("seed", "18446744073709551616", "", o), InputError);
  EXPECT_THROW(parse_option_text("nee", "yes", "", o), InputError);
}

// A scene value that does not fit its option is an error, never clamped.
TEST(RenderOptions, SceneNumbersOutOfRangeAreErrors) {
  test::expect_load_error(std::filesystem::temp_directory_path(), scene_with(R"({"spp": 1099511627776})"),
                          "render.spp");
  test::expect_load_error(std::filesystem::temp_directory_path(), scene_with(R"({"max_depth": -1})"),
                          "render.max_depth");
  test::expect_load_error(std::filesystem::temp_directory_path(), scene_with(R"({"nee": "on"})"), "render.nee");
  test::expect_load_error(std::filesystem::temp_directory_path(), scene_with(R"({"effects": "shadow"})"),
                          "render.effects");
}

// One name table per enum: parsing a printed name gives the value back.
TEST(EnumNames, ParseWhatIsPrinted) {
  for (uint32_t i = 0; i < std::size(EnumNames<AccelKind>::names); ++i)
    EXPECT_EQ(parse_enum<AccelKind>(enum_name(static_cast<AccelKind>(i)), "t"), static_cast<AccelKind>(i));
  for (uint32_t i = 0; i < std::size(EnumNames<IntegratorKind>::names); ++i)
    EXPECT_EQ(parse_enum<IntegratorKind>(enum_name(static_cast<IntegratorKind>(i)), "t"),
              static_cast<IntegratorKind>(i));
  EXPECT_STREQ(enum_name(IntegratorKind::Path), "path");
  EXPECT_STREQ(enum_name(SamplerKind::Stratified), "stratified");
  EXPECT_STREQ(enum_name(TriangleTest::MollerTrumbore), "moller-trumbore");
  EXPECT_THROW(parse_enum<SamplerKind>("jitter", "t"), InputError);
}

// A comma-separated list of names (the bench commands' --accel, --samplers, --orders): each
// name in order, none for an empty text, and an empty name anywhere refused.
TEST(EnumNames, ParseACommaSeparatedList) {
  EXPECT_EQ(parse_enum_list<AccelKind>("grid,bvh,grid", "t"),
            (std::vector<AccelKind>{AccelKind::Grid, AccelKind::Bvh, AccelKind::Grid}));
  EXPECT_EQ(parse_enum_list<StreamOrder>("sorted", "t"), std::vector<StreamOrder>{StreamOrder::Sorted});
  EXPECT_TRUE(parse_enum_list<StreamOrder>("", "t").empty());
  for (const char* bad : {",", "queue,", ",queue", "queue,,sorted", "queue,random"})
    EXPECT_THROW(parse_enum_list<StreamOrder>(bad, "t"), InputError) << bad;
}

}  // namespace
}  // namespace tracer
