#include "golden/golden_manifest.h"

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "io/output_batch.h"
#include "io/text_file.h"
#include "scene/scene_types.h"

namespace tracer {
namespace {

constexpr const char* kFormat = "tracer-golden/1";

// A golden's name names a test and a file; at most kMaxGoldenName characters, which also bounds
// what `golden update --filter` (std::regex, which recurses per character) searches.
constexpr size_t kMaxGoldenName = 100;

bool valid_name(const std::string& name) {
  if (name.empty() || name.front() == '-' || name.size() > kMaxGoldenName) return false;
  return std::all_of(name.begin(), name.end(),
                     [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-'; });
}

RenderOptions read_entry_options(const Json& value, const std::string& path, const std::string& file) {
  JsonObject obj(value, path, file);
  RenderOptions o;
  read_options(obj, nullptr, o);
  obj.finish();
  return o;
}

std::optional<GoldenTolerance> read_compare(JsonObject& entry) {
  const Json* v = entry.find("compare");
  if (!v || (v->is_string() && v->get<std::string>() == "exact")) return std::nullopt;
  if (!v->is_object())
    entry.fail("compare", "expected \"exact\" or {\"fail\", \"failpercent\", \"why\"}, got " + describe(*v));
  JsonObject obj(*v, entry.child("compare"), entry.file());
  GoldenTolerance t;
  t.fail = obj.number("fail");
  t.failpercent = obj.number_or("failpercent", 0.0f);
  t.why = obj.string("why");
  if (!(t.fail >= 0.0f)) obj.fail("fail", "must be >= 0");
  if (!(t.failpercent >= 0.0f && t.failpercent <= 100.0f)) obj.fail("failpercent", "must be in [0, 100]");
  if (t.why.size() < 10) obj.fail("why", "a tolerance needs a reason: say why this golden cannot be exact");
  obj.finish();
  return t;
}

GoldenEntry read_entry(const std::string& name, const Json& value, const std::string& path, const std::string& file) {
  JsonObject obj(value, path, file);
  if (!valid_name(name))
    fail_at(file, path, "golden names use a-z, 0-9 and '-', at most 100 characters (they name tests and files)");
  GoldenEntry e;
  e.name = name;
  e.scene = obj.string("scene");
  if (e.scene.empty() || std::filesystem::path(e.scene).is_absolute())
    obj.fail("scene", "expected a path relative to the source root, got \"" + e.scene + "\"");
  const std::filesystem::path normal = std::filesystem::path(e.scene).lexically_normal();
  if (normal.empty() || *normal.begin() == "..")
    obj.fail("scene", "\"" + e.scene + "\" leaves the source root; a golden's scene lies inside it");
  const Json empty = Json::object();
  const Json* options = obj.find("options");
  e.options = read_entry_options(options ? *options : empty, obj.child("options"), file);
  const std::string image = obj.string_or("image", "render");
  if (image != "render" && image != "sample-map")
    obj.fail("image", "expected \"render\" (the default) or \"sample-map\", got \"" + image + "\"");
  e.image = image == "sample-map" ? GoldenImage::SampleMap : GoldenImage::Render;
  e.hash = obj.string_or("hash", "");
  if (!e.hash.empty() && (e.hash.rfind("sha1:", 0) != 0 || e.hash.size() != 45))
    obj.fail("hash", "expected \"sha1:\" and 40 hex digits, got \"" + e.hash + "\"");
  if (!e.hash.empty() && !e.options.complete())
    obj.fail("options",
             "a golden with a hash records every option (integrator, sampler, spp, seed, width, height, accel, "
             "max_depth); run `tracer golden update`");
  e.tolerance = read_compare(obj);
  obj.finish();
  return e;
}

}  // namespace

std::string GoldenManifest::image_path(const GoldenEntry& e) const {
  return (std::filesystem::path(root) / "golden" / (e.name + ".exr")).string();
}

std::string GoldenManifest::scene_path(const GoldenEntry& e) const {
  return (std::filesystem::path(root) / e.scene).string();
}

const GoldenEntry& GoldenManifest::find(const std::string& name) const {
  for (const GoldenEntry& e : entries)
    if (e.name == name) return e;
  throw InputError(path + ": goldens: no entry named \"" + name + "\"");
}

std::string manifest_path(const std::string& root) {
  return (std::filesystem::path(root) / "golden" / "manifest.json").string();
}

GoldenManifest read_manifest(const std::string& root) {
  GoldenManifest m;
  m.root = root;
  m.path = manifest_path(root);
  const Json doc = parse_json_text(read_text_file(m.path, "the golden manifest"), m.path);
  JsonObject top(doc, "", m.path);
  const std::string format = top.string("format");
  if (format != kFormat) top.fail("format", "expected \"" + std::string(kFormat) + "\", got \"" + format + "\"");
  const Json& goldens = top.get("goldens");
  if (!goldens.is_object()) top.fail("goldens", "expected an object from name to entry, got " + describe(goldens));
  for (const auto& item : goldens.items())
    m.entries.push_back(read_entry(item.key(), item.value(), "goldens." + item.key(), m.path));
  top.finish();
  return m;  // nlohmann's object keeps keys sorted, so entries are sorted by name
}

void add_manifest(OutputBatch& outputs, const GoldenManifest& manifest) {
  nlohmann::ordered_json doc;
  doc["format"] = kFormat;
  doc["goldens"] = nlohmann::ordered_json::object();
  // ordered_json's operator[] and emplace compare the new key with every key held, which made
  // writing n entries take n^2/2 comparisons (200k goldens: 45 s). The names are distinct and
  // sorted (read_manifest), so each entry is appended to the object's vector of pairs.
  using Pairs = std::vector<std::pair<const std::string, nlohmann::ordered_json>>;
  Pairs& goldens = doc["goldens"].get_ref<nlohmann::ordered_json::object_t&>();
  goldens.reserve(manifest.entries.size());
  for (const GoldenEntry& e : manifest.entries) {
    nlohmann::ordered_json entry;
    entry["scene"] = e.scene;
    entry["options"] = e.options.to_json();
    if (e.image == GoldenImage::SampleMap) entry["image"] = "sample-map";
    if (!e.hash.empty()) entry["hash"] = e.hash;
    if (e.tolerance)
      entry["compare"] = {
          {"fail", e.tolerance->fail}, {"failpercent", e.tolerance->failpercent}, {"why", e.tolerance->why}};
    else
      entry["compare"] = "exact";
    goldens.emplace_back(e.name, std::move(entry));
  }
  outputs.add(manifest.path, doc.dump(2) + "\n");
}

}  // namespace tracer
