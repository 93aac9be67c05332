// The CLI's subcommands; each returns the process exit code (0 ok, 1 comparison failed,
// 2 bad input or error). main.cpp parses the command line with CLI11.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "image/compare.h"
#include "golden/golden_update.h"
#include "scene/scene.h"

namespace tracer {

struct RenderCommand {
  std::string scene, output, stats;
  std::map<std::string, std::optional<std::string>> options;  // --spp 4: "spp" -> "4", for every option of the table
  int threads = 0;
  std::string device = "cpu";
  std::string samples;  // --samples A:B: write samples [A, B) to a partial file
  bool quiet = false;
};

struct GpuPackCommand {
  std::string dir, root = ".", runner;
  int threads = 0;
};

struct CompareCommand {
  std::string a, b, diff;
  CompareOptions options;
};

struct GoldenCheckCommand {
  std::string name, root = ".", report, device = "cpu";
  int threads = 0;
};

struct GoldenReportCommand {
  std::string report;
  bool reset = false;
};

struct BenchDeviceCommand {
  std::string device = "cuda", scenes = "scenes";
  int frames = 5;
  int threads = 0;
};

struct MergeCommand {
  std::vector<std::string> parts;
  std::string output;
};

struct BenchConvergeCommand {
  std::string scene, ref, csv, plot, spp = "1,4,16,64,256", nee = "scene";
  uint32_t ref_spp = 0, width = 0, height = 0;
  int threads = 0;
};

struct BenchTradeCommand {
  std::string scene, ref;
  uint32_t spp = 64, ref_spp = 0, width = 0, height = 0;
  int threads = 0;
};

struct BenchRaysCommand {
  std::string scene, accel;
  uint32_t incoherent = 1u << 22, grid_resolution = 0;
  int threads = 0;
};

struct BenchWatertightCommand {
  std::vector<std::string> meshes;  // closed OBJ meshes; none: a generated icosphere and cube (and the bunny)
  uint32_t edge_points = 16;
  int threads = 0;
};

struct GenerateCommand {
  std::string kind, output;
  uint32_t triangles = 100000;
};

int run_render(const RenderCommand& cmd);
RenderOverrides scene_overrides(const RenderCommand& cmd);  // the options given on the command line
int run_bundle(const RenderCommand& cmd);
int run_gpu_pack(const GpuPackCommand& cmd);
int run_bench_rays(const BenchRaysCommand& cmd);
int run_bench_watertight(const BenchWatertightCommand& cmd);
int run_generate(const GenerateCommand& cmd);
int run_bench_converge(const BenchConvergeCommand& cmd);
int run_bench_trade(const BenchTradeCommand& cmd);
int run_merge(const MergeCommand& cmd);
int run_bench_device(const BenchDeviceCommand& cmd);
int run_info(const std::string& scene_path);
int run_compare(const CompareCommand& cmd);
// 0 identical, 1 differs, 2 cannot check, kExitSkipped when the device is not on this
// machine (CTest's SKIP_RETURN_CODE).
constexpr int kExitSkipped = 77;
int run_golden_check(const GoldenCheckCommand& cmd);
int run_golden_update(const UpdateRequest& request);
int run_golden_report(const GoldenReportCommand& cmd);
int run_golden_list(const std::string& root);

}  // namespace tracer
