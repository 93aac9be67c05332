// `tracer gpu-pack DIR`: everything a bare GPU machine needs to prove CPU/GPU bit-identity,
// in one directory well under 64 MiB: a scene bundle per golden with the golden's pixel
// hash, the kernel-level parity cases with the SHA-1 of the CPU's answers, the
// self-contained runner (tracer-gpu) and run.sh, which runs them all and prints one table.
// The directory is assembled beside DIR and renamed into place, so a failure leaves nothing.
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "bundle/scene_bundle.h"
#include "commands.h"
#include "golden_manifest.h"
#include "input_error.h"
#include "parity/parallel_for.h"
#include "parity/parity_suite.h"
#include "scene_loader.h"
#include "text_file.h"

namespace tracer {
namespace {

namespace fs = std::filesystem;
using parity::ParityCase;
using parity::ParityKind;

const char* kRunScript =
    "#!/bin/sh\n"
    "# Runs this GPU pack (written by `tracer gpu-pack`): every golden's scene bundle and every\n"
    "# CPU/GPU parity case on the GPU, or on the CPU with `./run.sh --device cpu`, and prints one\n"
    "# pass/fail table. Exit 0 when every entry matches the CPU bit for bit. docs/cuda.md.\n"
    "cd \"$(dirname \"$0\")\" && exec ./tracer-gpu pack . \"$@\"\n";

const char* kMathNames[] = {"sin", "cos", "tan", "asin", "acos", "atan2", "exp", "log", "pow"};
const char* kTraceScenes[] = {"cornell-box", "mesh", "refraction"};
const char* kAccels[] = {"bvh", "lbvh", "kdtree", "kdtree-median", "grid", "none"};

Scene golden_scene(const GoldenManifest& manifest, const std::string& name, const char* accel) {
  const GoldenEntry& e = manifest.find(name);
  RenderOverrides o = e.options.overrides();
  if (accel) o.accel = accel;
  return load_scene(manifest.scene_path(e), o);
}

// The cases of the GoogleTest parity suite (tests/test_cuda_parity.cpp), with the same
// inputs, plus traversal through every acceleration structure, the LBVH build of 2^20
// triangles and one whole golden's samples.
std::vector<ParityCase> parity_cases(const GoldenManifest& manifest) {
  std::vector<ParityCase> cases;
  for (uint32_t f = 0; f < parity::kMathFunctionCount; ++f)
    cases.push_back({std::string("math-") + kMathNames[f], {ParityKind::Math, f, f, 1u << 20, 0, {}, {}}, {}});
  cases.push_back({"philox", {ParityKind::Philox, 0, 7, 1u << 21, 0, {}, {}}, {}});
  cases.push_back({"shapes", {ParityKind::Shapes, 0, 11, 1u << 20, 0, {}, {}}, {}});
  for (const char* name : kTraceScenes) {
    const Scene bvh = golden_scene(manifest, name, "bvh");
    const BvhNode& root = bvh.bvh_nodes.at(0);  // ray origins fill the scene's bounds
    for (const char* accel : kAccels) {
      const Scene scene = std::string(accel) == "bvh" ? bvh : golden_scene(manifest, name, accel);
      const std::string label = std::string("trace-") + name + "-" + accel;
      cases.push_back({label, {ParityKind::Trace, 0, 13, 1u << 18, 0, root.lo, root.hi},
                       make_scene_bundle(scene, scene.view(), {0, scene.settings.spp}, label)});
    }
  }
  cases.push_back({"lbvh-build-1m", {ParityKind::Lbvh, 0, 17, 1u << 20, 0, {}, {}}, {}});
  const Scene sample = golden_scene(manifest, "cornell-box", nullptr);
  cases.push_back({"sample-cornell-box", {ParityKind::Sample, 0, 0, 0, 0, {}, {}},
                   make_scene_bundle(sample, sample.view(), {0, sample.settings.spp}, "sample-cornell-box")});
  return cases;
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

void write_pack(const GpuPackCommand& cmd, const std::string& runner, const fs::path& out) {
  const GoldenManifest manifest = read_manifest(cmd.root);
  fs::create_directories(out / "bundles");
  fs::create_directories(out / "parity");
  std::string list = "# kind name file expected: the golden's pixel hash, or - (the parity case holds its own)\n";
  for (const GoldenEntry& e : manifest.entries) {
    const Scene scene = load_scene(manifest.scene_path(e), e.options.overrides());
    const std::string file = "bundles/" + e.name + ".bundle";
    write_bundle((out / file).string(),
                 encode_scene_bundle(make_scene_bundle(scene, scene.view(), {0, scene.settings.spp}, e.scene)));
    list += "golden " + e.name + " " + file + " " + e.hash + "\n";
  }
  const unsigned threads = cmd.threads > 0 ? static_cast<unsigned>(cmd.threads) : default_thread_count();
  for (const ParityCase& c : parity_cases(manifest)) {
    const parity::ParityAnswers cpu = parity::evaluate_parity_case(c, false, threads);
    const std::string file = "parity/" + c.name + ".case";
    write_bundle((out / file).string(), parity::encode_parity_case(c, cpu));
    list += "parity " + c.name + " " + file + " -\n";
    std::fprintf(stderr, "parity case %s: %zu inputs\n", c.name.c_str(), cpu.inputs);
  }
  fs::copy_file(runner, out / "tracer-gpu");
  fs::permissions(out / "tracer-gpu", fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                          fs::perms::others_read | fs::perms::others_exec);
  write_text_atomically((out / "run.sh").string(), kRunScript);
  fs::permissions(out / "run.sh", fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                  fs::perm_options::add);
  write_text_atomically((out / "pack.tsv").string(), list);
}

}  // namespace

int run_gpu_pack(const GpuPackCommand& cmd) {
  const fs::path dir(cmd.dir);
  if (fs::exists(dir) && !(fs::is_directory(dir) && fs::is_empty(dir)))
    throw InputError(cmd.dir + ": exists and is not an empty directory; gpu-pack writes a new one");
  const fs::path parent = dir.parent_path().empty() ? "." : dir.parent_path();
  if (!fs::is_directory(parent)) throw InputError(cmd.dir + ": parent directory does not exist");
  const std::string runner = cmd.runner.empty() ? runner_beside_this_binary() : cmd.runner;
  if (!fs::is_regular_file(runner))
    throw InputError(runner + ": no tracer-gpu runner there (build it: cmake --build build --target tracer-gpu)");

  const fs::path temp = parent / (dir.filename().string() + ".partial-" + std::to_string(::getpid()));
  fs::remove_all(temp);
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

}  // namespace tracer
