// `tracer gpu-pack DIR`: everything a bare GPU machine needs to prove CPU/GPU bit-identity,
// in one directory well under 64 MiB: a scene bundle per golden with the golden's pixel
// hash, the kernel-level parity cases with the SHA-1 of the CPU's answers, the
// self-contained runner (tracer-gpu) and run.sh, which runs them all and prints one table.
// The directory is assembled beside DIR and renamed into place, so a failure leaves nothing.
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "bench/mesh_generators.h"
#include "bench/ray_sets.h"
#include "bundle/scene_bundle.h"
#include "cli/command_registry.h"
#include "cli/commands.h"
#include "golden/golden_manifest.h"
#include "io/input_error.h"
#include "io/interrupt.h"
#include "io/new_directory.h"
#include "io/output_batch.h"
#include "kernel/accel/trace_variants.h"
#include "options/enum_names.h"
#include "parity/parallel_for.h"
#include "parity/parity_suite.h"
#include "render/device_bvh.h"
#include "scene/scene_loader.h"
#include "scene/scene_types.h"

namespace tracer {

struct GpuPackCommand {
  std::string dir, root = ".", runner;
  int threads = 0;
};
namespace {

namespace fs = std::filesystem;
using parity::ParityCase;
using parity::ParityKind;

const char* kRunScript =
    "#!/bin/sh\n"
    "# Runs this GPU pack (written by `tracer gpu-pack`): every golden's scene bundle and every\n"
    "# CPU/GPU parity case on the GPU, or on the CPU with `./run.sh --device cpu`, and prints one\n"
    "# pass/fail table (exit 0 when every entry matches the CPU bit for bit); then, on the GPU,\n"
    "# the device, its kernel's registers and occupancy, and the bench tables. docs/cuda.md.\n"
    "cd \"$(dirname \"$0\")\" || exit 2\n"
    "./tracer-gpu pack . \"$@\"\n"
    "status=$?\n"
    "case \" $* \" in *\" cpu \"*) exit $status ;; esac\n"
    "./tracer-gpu device && ./tracer-gpu bench . --repeat 20\n"
    "exit $status\n";

const char* kMathNames[] = {"sin", "cos", "tan", "asin", "acos", "atan2", "exp", "log", "pow"};
const char* kTraceScenes[] = {"cornell-box", "mesh", "refraction"};
const AccelKind kAccels[] = {AccelKind::Bvh,          AccelKind::Lbvh, AccelKind::Kdtree,
                             AccelKind::KdtreeMedian, AccelKind::Grid, AccelKind::None};

Scene golden_scene(const GoldenManifest& manifest, const std::string& name, std::optional<AccelKind> accel) {
  const GoldenEntry& e = manifest.find(name);
  RenderOverrides o = golden_overrides(manifest, e);
  o.accel = accel ? accel : e.options.accel;
  return load_scene(manifest.scene_path(e), o);
}

// The cases of the GoogleTest parity suite (tests/cuda/test_cuda_parity.cpp), with the same
// inputs, plus traversal through every acceleration structure, the LBVH build of 2^20
// triangles and one whole golden's samples.
std::vector<ParityCase> parity_cases(const GoldenManifest& manifest) {
  std::vector<ParityCase> cases;
  for (uint32_t f = 0; f < parity::kMathFunctionCount; ++f)
    cases.push_back({std::string("math-") + kMathNames[f], {ParityKind::Math, f, f, 1u << 20, 0, {}, {}}, {}});
  cases.push_back({"philox", {ParityKind::Philox, 0, 7, 1u << 21, 0, {}, {}}, {}});
  cases.push_back({"shapes", {ParityKind::Shapes, 0, 11, 1u << 20, 0, {}, {}}, {}});
  cases.push_back({"microfacet-bsdfs", {ParityKind::Bsdf, 0, 23, 1u << 20, 0, {}, {}}, {}});
  for (const char* name : kTraceScenes) {
    const Scene bvh = golden_scene(manifest, name, AccelKind::Bvh);
    const BvhNode& root = bvh.bvh_nodes.at(0);  // ray origins fill the scene's bounds
    for (const AccelKind accel : kAccels) {
      const Scene scene = accel == AccelKind::Bvh ? bvh : golden_scene(manifest, name, accel);
      const std::string label = std::string("trace-") + name + "-" + enum_name(accel);
      cases.push_back({label,
                       {ParityKind::Trace, 0, 13, 1u << 18, 0, root.lo, root.hi},
                       make_scene_bundle(scene, scene.view(), {0, scene.settings.spp}, label)});
    }
  }
  cases.push_back({"adaptive-decision", {ParityKind::Adaptive, 0, 19, 1u << 20, 0, {}, {}}, {}});
  cases.push_back({"lbvh-build-1m", {ParityKind::Lbvh, 0, 17, 1u << 20, 0, {}, {}}, {}});
  const Scene sample = golden_scene(manifest, "cornell-box", std::nullopt);
  cases.push_back({"sample-cornell-box",
                   {ParityKind::Sample, 0, 0, 0, 0, {}, {}},
                   make_scene_bundle(sample, sample.view(), {0, sample.settings.spp}, "sample-cornell-box")});
  // The stream schedule's stages against the megakernel, sample by sample, at a width that
  // splits pixels between batches: Whitted and the path tracer.
  for (const char* golden : {"cornell-box", "cornell-box-path"}) {
    const Scene scene = golden_scene(manifest, golden, std::nullopt);
    const std::string name = std::string("stream-") + golden;
    cases.push_back({name,
                     {ParityKind::Stream, 0, 0, 4099, 0, {}, {}},
                     make_scene_bundle(scene, scene.view(), {0, scene.settings.spp}, name)});
  }
  return cases;
}

// The scenes of `tracer bench device` as bundles (Whitted, 720x480 unless the row says):
// the Cornell box per sampler, per effect and per resolution, and a generated 100k-triangle
// mesh at 4 spp; table `rays`, traversal alone on the mesh; then the stream schedule against the
// megakernel (table `schedule`: the main and mesh bundles and the path-traced Cornell box at
// 16 spp, each under both schedules).
// bench.tsv rows: "TABLE LABEL FILE [SCHEDULE]"; `tracer-gpu bench` times them.
std::string write_bench(const fs::path& root, const fs::path& out) {
  struct Sampler {
    const char* label;
    SamplerKind sampler;
    uint32_t spp;
  };
  const Sampler samplers[] = {{"1spp-center", SamplerKind::Center, 1},
                              {"2spp-stochastic", SamplerKind::Stochastic, 2},
                              {"4spp-grid", SamplerKind::Grid, 4}};
  fs::create_directories(out / "bench");
  std::string list = "# table label file: `tracer-gpu bench DIR` times every row\n";
  const auto add = [&](const std::string& table, const std::string& label, const std::string& scene_path,
                       uint32_t width, uint32_t height, const Sampler& s, Effects effects,
                       const std::string& fourth_field = "") {
    RenderOverrides o;
    o.width = width, o.height = height, o.sampler = s.sampler, o.spp = s.spp, o.effects = effects,
    o.integrator = IntegratorKind::Whitted;
    throw_if_interrupted();
    const Scene scene = load_scene(scene_path, o);
    const std::string file = "bench/" + table + "-" + label + ".bundle";
    write_bundle((out / file).string(),
                 encode_scene_bundle(make_scene_bundle(scene, scene.view(), {0, scene.settings.spp}, label)));
    list += table + " " + label + " " + file + (fourth_field.empty() ? "" : " " + fourth_field) + "\n";
  };
  const std::string cornell = (root / "scenes/cornell-box.json").string();
  for (const Sampler& s : {samplers[0], samplers[2]})
    add("main", std::string("cornell-box-") + s.label, cornell, 720, 480, s, kEffectAll);
  const std::pair<const char*, Effects> effects[] = {{"none", kEffectNone},
                                                     {"shadows", kEffectShadows},
                                                     {"reflections", kEffectReflection},
                                                     {"refractions", kEffectRefraction},
                                                     {"all", kEffectAll}};
  for (const auto& [name, mask] : effects)
    for (const Sampler& s : samplers) add("effects", std::string(name) + "-" + s.label, cornell, 720, 480, s, mask);
  const uint32_t sizes[][2] = {{640, 480}, {1280, 720}, {1920, 1080}};
  for (const auto& size : sizes)
    for (const Sampler& s : samplers)
      add("resolution", std::to_string(size[0]) + "x" + std::to_string(size[1]) + "-" + s.label, cornell, size[0],
          size[1], s, kEffectAll);

  const fs::path temp = make_new_directory(fs::temp_directory_path(), "tracer-gpu-pack-mesh-");
  std::string sphere_4spp;  // the mesh's 4 spp bundle
  try {
    const std::vector<MeshTriangle> mesh = generate_mesh("sphere", 100000);
    write_obj(mesh, (temp / "sphere-100k.obj").string());
    const std::string sphere_json = R"({
  "format": "tracer-scene/1",
  "camera": { "from": [0, 0.6, 4], "to": [0, 0, 0], "vfov": 40 },
  "film": { "width": 720, "height": 480 },
  "render": { "integrator": "whitted", "spp": 1, "sampler": "center", "max_depth": 8 },
  "ambient": [0.05, 0.05, 0.05],
  "materials": {
    "clay": { "type": "phong", "diffuse": [0.8, 0.5, 0.3], "specular": [0.5, 0.5, 0.5], "shininess": 40 },
    "floor": { "type": "lambert", "albedo": [0.7, 0.7, 0.7] }
  },
  "lights": [ { "type": "point", "position": [-2, 4, 3], "intensity": [25, 25, 25] } ],
  "shapes": [
    { "type": "quad", "corner": [-4, -1.5, 3], "u": [8, 0, 0], "v": [0, 0, -8], "material": "floor" },
    { "type": "mesh", "file": "sphere-100k.obj", "material": "clay" }
  ]
}
)";
    write_file_atomically((temp / "sphere-100k.json").string(), sphere_json);
    // One sampler (4 spp, the schedule table's row too): each bundle of it carries the 8 MB mesh.
    add("mesh", "sphere-" + std::to_string(mesh.size()) + "tri-" + samplers[2].label,
        (temp / "sphere-100k.json").string(), 720, 480, samplers[2], kEffectAll);
    sphere_4spp = "bench/mesh-sphere-" + std::to_string(mesh.size()) + "tri-4spp-grid.bundle";
    // Traversal alone (cuda/runner/ray_bench.h): the sphere without its floor, a triangle mesh
    // that the GPU's wide_bvh_triangles trace variant runs. The runner makes the mesh again
    // (`mesh:sphere:100000`, the same triangles under the same SAH build) in the view of a
    // 1,280-triangle one, so the pack does not carry its 8 MB a third time.
    const std::string floor =
        R"({ "type": "quad", "corner": [-4, -1.5, 3], "u": [8, 0, 0], "v": [0, 0, -8], "material": "floor" },)";
    std::string alone = sphere_json;
    alone.erase(alone.find(floor), floor.size());
    alone.replace(alone.find("sphere-100k.obj"), std::string("sphere-100k.obj").size(), "sphere-small.obj");
    write_obj(generate_mesh("sphere", 1280), (temp / "sphere-small.obj").string());
    write_file_atomically((temp / "sphere-100k-alone.json").string(), alone);
    add("rays", "sphere-" + std::to_string(mesh.size()) + "tri", (temp / "sphere-100k-alone.json").string(), 720, 480,
        samplers[0], kEffectAll, "mesh:sphere:100000");
    // A bare mesh framed as `tracer bench rays` frames an OBJ file (bench/ray_sets.h).
    const auto add_bare_mesh = [&](const std::string& label, const std::vector<MeshTriangle>& triangles,
                                   const std::string& fourth_field) {
      Vec3 lo = triangles.at(0).p[0], hi = lo;
      for (const MeshTriangle& t : triangles)
        for (const Vec3& p : t.p) lo = min_of(lo, p), hi = max_of(hi, p);
      const Vec3 eye = mesh_bench_eye(lo, hi), centre = (lo + hi) * 0.5f;
      const auto vec = [](Vec3 v) {
        char text[96];
        std::snprintf(text, sizeof text, "[%.9g, %.9g, %.9g]", v.x, v.y, v.z);
        return std::string(text);
      };
      write_obj(triangles, (temp / (label + ".obj")).string());
      write_file_atomically((temp / (label + ".json")).string(),
                            R"({ "format": "tracer-scene/1", "camera": { "from": )" + vec(eye) + R"(, "to": )" +
                                vec(centre) + R"(, "vfov": )" + std::to_string(kMeshBenchFov) + R"( },
  "film": { "width": 720, "height": 480 }, "render": { "integrator": "whitted", "spp": 1, "sampler": "center" },
  "materials": { "m": { "type": "lambert", "albedo": [0.7, 0.7, 0.7] } },
  "shapes": [ { "type": "mesh", "file": ")" +
                                label + R"(.obj", "material": "m" } ] })");
      add("rays", label, (temp / (label + ".json")).string(), 720, 480, samplers[0], kEffectAll, fourth_field);
    };
    // the bunny, where ci/fetch-bunny.sh put it
    const fs::path bunny = root / "scenes/generated/bunny.obj";
    if (fs::is_regular_file(bunny)) add_bare_mesh("bunny", load_obj(bunny.string(), bunny.string(), "bunny"), "");
    // the 10^6-triangle terrain of ci/generate-meshes.sh, 80 MB as a bundle: the runner makes it
    // (`mesh:terrain:1000000`) in the view of a 4,096-triangle one, whose box differs only in
    // height (0.811 against 0.822 of 4 x 4)
    add_bare_mesh("terrain-1m", generate_mesh("terrain", 4096), "mesh:terrain:1000000");
  } catch (...) {
    fs::remove_all(temp);
    throw;
  }
  fs::remove_all(temp);

  RenderOverrides path;
  path.width = 720, path.height = 480, path.spp = 16;
  const Scene path_scene = load_scene((root / "scenes/cornell-box-path.json").string(), path);
  write_bundle((out / "bench/schedule-cornell-box-path-16spp.bundle").string(),
               encode_scene_bundle(make_scene_bundle(path_scene, path_scene.view(), {0, 16}, "cornell-box-path")));
  const std::string rows[][2] = {{"cornell-box-1spp-center", "bench/main-cornell-box-1spp-center.bundle"},
                                 {"cornell-box-4spp-grid", "bench/main-cornell-box-4spp-grid.bundle"},
                                 {"sphere-4spp-grid", sphere_4spp},
                                 {"cornell-box-path-16spp", "bench/schedule-cornell-box-path-16spp.bundle"}};
  for (const auto& [label, file] : rows)
    for (const char* schedule :
         {"megakernel", "stream:262144", "stream:4194304", "stream:262144:sorted", "stream:4194304:sorted"})
      list += std::string("schedule ") + label + "-" + (schedule[0] == 'm' ? "megakernel" : schedule) + " " + file +
              " " + schedule + "\n";
  return list;
}

std::string runner_beside_this_binary() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? "tracer-gpu" : (self.parent_path() / "tracer-gpu").string();
}

uint64_t directory_bytes(const fs::path& dir) {
  uint64_t bytes = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file()) bytes += entry.file_size();
  return bytes;
}

void write_scene_bundle(const Scene& scene, const std::string& scene_file, const fs::path& path,
                        bool keep_wide_tree = false) {
  write_bundle(path.string(), encode_scene_bundle(make_scene_bundle(scene, scene.view(), {0, scene.settings.spp},
                                                                    scene_file, keep_wide_tree)));
}

// The trace variant the device runs a bundle of `scene` on (`wide_tree`: the bundle keeps bvh's
// 8-wide tree, else the device walks the binary tree, with pair records where it builds them).
int bundle_trace_variant(const Scene& scene, bool wide_tree) {
  SceneView view = scene.view();
  if (!wide_tree) view.wide_node_count = 0;
  return device_trace_variant(view);
}

// A golden that renders an image, as loaded: its scene's FeatureBit mask and settings.
struct LoadedGolden {
  const GoldenEntry* entry;
  uint32_t features;
  RenderSettings settings;
};

// Rows "golden NAME@ACCEL@stream" for the stream schedule's trace variants
// (kernel/accel/trace_variants.h) that no golden runs with its own structure: the first golden
// whose scene runs the variant with another structure, rendered with that one; ACCEL "bvh8" is
// bvh with its 8-wide tree kept in the bundle, which the device then walks. Every structure
// renders every golden's image (tests/determinism/test_accel_identity.cpp), so the expected
// hash is the golden's.
std::string trace_variant_rows(const GoldenManifest& manifest, const std::vector<LoadedGolden>& goldens,
                               const fs::path& out, std::vector<bool>& covered) {
  std::vector<std::string> accels = accepted_scene_types().at("accel");
  accels.push_back("bvh8");
  std::string rows;
  for (const LoadedGolden& g : goldens)
    for (const std::string& accel : accels) {
      const bool wide_tree = accel == "bvh8";
      RenderSettings settings = g.settings;
      settings.accel = wide_tree ? AccelKind::Bvh : parse_enum<AccelKind>(accel, "accel");
      // With pair records where a scene of triangles may have them; the loaded tree says (a
      // root that is a leaf has none).
      const bool may_pair = device_bvh_for(g.features, wide_tree) == DeviceBvh::Pairs;
      const int likely = trace_variant_of(g.features, settings, wide_tree, may_pair);
      if (likely < 0 || covered[likely]) continue;
      throw_if_interrupted();
      RenderOverrides options = golden_overrides(manifest, *g.entry);
      options.accel = settings.accel;
      const Scene scene = load_scene(manifest.scene_path(*g.entry), options);
      const int v = bundle_trace_variant(scene, wide_tree);
      if (v < 0 || covered[v]) continue;
      covered[v] = true;
      const std::string name = g.entry->name + "@" + accel, file = "bundles/" + name + ".bundle";
      write_scene_bundle(scene, g.entry->scene, out / file, wide_tree);
      rows += "golden " + name + "@stream " + file + " " + g.entry->hash + " stream:4099\n";
    }
  return rows;
}

void write_pack(const GpuPackCommand& cmd, const std::string& runner, const fs::path& out) {
  const GoldenManifest manifest = read_manifest(cmd.root);
  fs::create_directories(out / "bundles");
  fs::create_directories(out / "parity");
  std::string list = "# kind name file expected: the golden's pixel hash, or - (the parity case holds its own)\n";
  std::vector<bool> traced(kTraceVariantCount);
  std::vector<LoadedGolden> renders;
  for (const GoldenEntry& e : manifest.entries) {
    throw_if_interrupted();
    const Scene scene = load_scene(manifest.scene_path(e), golden_overrides(manifest, e));
    const std::string file = "bundles/" + e.name + ".bundle";
    write_scene_bundle(scene, e.scene, out / file);
    const std::string kind = e.image == GoldenImage::SampleMap ? "sample-map " : "golden ";
    list += kind + e.name + " " + file + " " + e.hash + " megakernel\n";
    // The stream schedule at a width that splits pixels between batches, with its queues in
    // their own order and sorted by their rays' keys: the same image.
    list += kind + e.name + "@stream " + file + " " + e.hash + " stream:4099\n";
    list += kind + e.name + "@sorted " + file + " " + e.hash + " stream:4099:sorted\n";
    const int v = bundle_trace_variant(scene, false);
    if (v >= 0) traced[v] = true;
    if (e.image == GoldenImage::Render) renders.push_back({&e, scene.features, scene.settings});
  }
  list += trace_variant_rows(manifest, renders, out, traced);
  const unsigned threads = cmd.threads > 0 ? static_cast<unsigned>(cmd.threads) : default_thread_count();
  for (const ParityCase& c : parity_cases(manifest)) {
    throw_if_interrupted();
    const parity::ParityAnswers cpu = parity::reference_parity_answers(c, threads);
    const std::string file = "parity/" + c.name + ".case";
    write_bundle((out / file).string(), parity::encode_parity_case(c, cpu));
    list += "parity " + c.name + " " + file + " -\n";
    std::fprintf(stderr, "parity case %s: %zu inputs\n", c.name.c_str(), cpu.inputs);
  }
  throw_if_interrupted();
  fs::copy_file(runner, out / "tracer-gpu");
  fs::permissions(out / "tracer-gpu", fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                          fs::perms::others_read | fs::perms::others_exec);
  write_file_atomically((out / "run.sh").string(), kRunScript);
  fs::permissions(out / "run.sh", fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                  fs::perm_options::add);
  write_file_atomically((out / "pack.tsv").string(), list);
  write_file_atomically((out / "bench.tsv").string(), write_bench(cmd.root, out));
  throw_if_interrupted();
}

}  // namespace

static int run_gpu_pack(const GpuPackCommand& cmd) {
  const fs::path dir = without_trailing_separator(cmd.dir);  // "pack/" is "pack", whose parent is "."
  const fs::file_status st = fs::symlink_status(dir);
  if (fs::is_symlink(st))
    throw InputError(cmd.dir + ": a symbolic link; gpu-pack writes a new directory, or into an empty one, by name");
  if (fs::exists(st) && !(fs::is_directory(st) && fs::is_empty(dir)))
    throw InputError(cmd.dir + ": exists and is not an empty directory; gpu-pack writes a new one");
  const fs::path parent = dir.parent_path().empty() ? "." : dir.parent_path();
  if (!fs::is_directory(parent))
    throw InputError(cmd.dir + ": parent directory " + parent.string() + " does not exist");
  const std::string runner = cmd.runner.empty() ? runner_beside_this_binary() : cmd.runner;
  if (!fs::is_regular_file(runner))
    throw InputError(runner + ": no tracer-gpu runner there (build it: cmake --build build --target tracer-gpu)");

  // The pack is staged in a directory of its own making, renamed into place when complete; an
  // interrupting signal removes it (io/interrupt.h).
  const InterruptsNoted noted;
  const fs::path temp = make_new_directory(parent, dir.filename().string() + ".partial-");
  try {
    write_pack(cmd, runner, temp);
    fs::rename(temp, dir);
  } catch (...) {
    std::error_code ec;
    fs::remove_all(temp, ec);
    throw;
  }
  std::printf("wrote %s (%.1f MiB). Run it on a GPU machine: %s/run.sh\n", cmd.dir.c_str(),
              static_cast<double>(directory_bytes(dir)) / (1 << 20), cmd.dir.c_str());
  return 0;
}

const RegisterCommand kGpuPackCommand(
    {"", "gpu-pack", "write the GPU pack: golden bundles, parity cases, tracer-gpu and run.sh", [](CLI::App& app) {
       auto cmd = std::make_shared<GpuPackCommand>();
       app.add_option("dir", cmd->dir, "new directory to create")->required();
       app.add_option("--root", cmd->root, "source root holding golden/ and scenes/ (default .)");
       app.add_option("--runner", cmd->runner, "tracer-gpu binary to include (default: beside this tracer)");
       add_threads_option(app, cmd->threads);
       return [cmd] { return run_gpu_pack(*cmd); };
     }});

}  // namespace tracer
