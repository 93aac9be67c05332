// tracer-gpu: the self-contained GPU runner. It links the kernel headers, cuda/ and the
// static CUDA runtime only (no OpenImageIO, loaders or OpenMP), so it runs on a bare GPU
// machine. It renders scene bundles and evaluates parity cases written by `tracer bundle`
// and `tracer gpu-pack`, on the GPU or, with --device cpu, on the CPU from the same code.
// Exit codes: 0 pass, 1 a hash or answer differs, 2 bad input or no usable device.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>

#include "bundle/scene_bundle.h"
#include "cpu_adaptive.h"
#include "cpu_film.h"
#include "gpu_adaptive.h"
#include "gpu_film.h"
#include "image/pixel_hash.h"
#include "io/out_of_memory.h"
#include "io/output_paths.h"
#include "io/sha1.h"
#include "io/standard_output.h"
#include "io/text_file.h"
#include "io/thread_start.h"
#include "kernel/accel/trace_variants.h"
#include "parity/parity_gpu.h"
#include "parity/parity_suite.h"
#include "ray_bench.h"
#include "render/device_bvh.h"
#include "render/device_error.h"

namespace tracer {
namespace {

const char* kUsage =
    "usage: tracer-gpu render BUNDLE [--device cuda|cpu] [--threads N] [--repeat N] [--expect sha1:HASH] [-o FILM]\n"
    "                                [--schedule megakernel|stream] [--stream-width N] [--stream-order queue|sorted]\n"
    "       tracer-gpu parity CASE [--device cuda|cpu] [--threads N]\n"
    "       tracer-gpu pack DIR [--device cuda|cpu] [--threads N] [--repeat N]\n"
    "       tracer-gpu bench DIR [--device cuda|cpu] [--threads N] [--repeat N]\n"
    "       tracer-gpu device\n";

constexpr uint32_t kMaxStreamWidth = 1u << 24;  // as the tracer's render.stream_width

struct Options {
  std::string command, input, device = "cuda", expect, output;
  std::optional<Schedule> schedule;  // the bundle's when unset
  uint32_t stream_width = 0;         // the bundle's when 0
  std::optional<StreamOrder> stream_order;  // the bundle's when unset
  unsigned threads = 0;
  uint32_t repeat = 1;
};

uint32_t parse_count(const std::string& flag, const std::string& text, uint32_t max) {
  uint32_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value == 0 || value > max)
    throw InputError(flag + " " + text + ": expected a whole number from 1 to " + std::to_string(max));
  return value;
}

Schedule parse_schedule(const std::string& text) {
  if (text == "megakernel") return Schedule::Megakernel;
  if (text == "stream") return Schedule::Stream;
  throw InputError("--schedule " + text + ": expected megakernel or stream");
}

StreamOrder parse_stream_order(const std::string& text) {
  if (text == "queue") return StreamOrder::Queue;
  if (text == "sorted") return StreamOrder::Sorted;
  throw InputError("--stream-order " + text + ": expected queue or sorted");
}

// A pack or bench row's schedule field: "megakernel", "stream:WIDTH" or "stream:WIDTH:ORDER".
Options with_schedule(Options o, const std::string& field, const std::string& where) {
  const size_t colon = field.find(':'), second = colon == std::string::npos ? colon : field.find(':', colon + 1);
  try {
    o.schedule = parse_schedule(field.substr(0, colon));
    if (colon != std::string::npos)
      o.stream_width =
          parse_count("--stream-width", field.substr(colon + 1, second - colon - 1), kMaxStreamWidth);
    if (second != std::string::npos) o.stream_order = parse_stream_order(field.substr(second + 1));
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  }
  return o;
}

// The bundle's view with the schedule the options ask for.
SceneView view_for(const SceneBundle& b, const Options& o) {
  SceneView view = b.view();
  if (o.schedule) view.settings.schedule = *o.schedule;
  if (o.stream_width != 0) view.settings.stream_width = o.stream_width;
  if (o.stream_order) view.settings.stream_order = *o.stream_order;
  return view;
}

Options parse(int argc, char** argv) {
  if (argc < 2) throw InputError(std::string("no command\n") + kUsage);
  Options o;
  o.command = argv[1];
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw InputError(a + " needs a value");
      return argv[++i];
    };
    if (a == "--device")
      o.device = value();
    else if (a == "--threads")
      o.threads = parse_count(a, value(), 4096);
    else if (a == "--repeat")
      o.repeat = parse_count(a, value(), 100000);
    else if (a == "--schedule")
      o.schedule = parse_schedule(value());
    else if (a == "--stream-width")
      o.stream_width = parse_count(a, value(), kMaxStreamWidth);
    else if (a == "--stream-order")
      o.stream_order = parse_stream_order(value());
    else if (a == "--expect")
      o.expect = value();
    else if (a == "-o" || a == "--output")
      o.output = value();
    else if (!a.empty() && a[0] == '-')
      throw InputError(a + ": unknown option\n" + kUsage);
    else if (o.input.empty())
      o.input = a;
    else
      throw InputError(a + ": one input only\n" + kUsage);
  }
  if (o.device != "cuda" && o.device != "cpu") throw InputError("--device " + o.device + ": expected cuda or cpu");
  if (o.command != "device" && o.input.empty()) throw InputError(o.command + ": needs an input\n" + kUsage);
  if (!o.output.empty()) {  // the film is written after the render: checked before it
    if (o.command != "render") throw InputError("-o " + o.output + ": only render writes a film");
    check_output_location(o.output, "-o");
    refuse_outputs_naming_inputs({{o.output, "-o"}}, {o.input});
  }
  if (!o.expect.empty()) {  // compared after the render: checked before it
    if (o.command != "render") throw InputError("--expect: only render compares its image's hash");
    const bool hex = o.expect.size() == 45 && o.expect.rfind("sha1:", 0) == 0 &&
                     std::all_of(o.expect.begin() + 5, o.expect.end(), [](char c) { return std::isxdigit(c) != 0; });
    if (!hex) throw InputError("--expect " + o.expect + ": expected sha1: and 40 hexadecimal digits (a golden's hash)");
    std::transform(o.expect.begin() + 5, o.expect.end(), o.expect.begin() + 5,
                   [](char c) { return static_cast<char>(std::toupper(c)); });
  }
  if (o.threads == 0) o.threads = default_thread_count();
  if (const std::string failure = thread_start_failure(o.threads); !failure.empty())
    throw InputError("--threads " + std::to_string(o.threads) + ": " + failure);
  return o;
}

struct Rendered {
  FilmBuffer film;                       // a uniform render's
  std::optional<AdaptiveFilm> adaptive;  // an adaptive render's (render.noise_threshold, target_error)
  RayCounts rays{};
  uint64_t nonfinite = 0, overflow = 0;
  double best_seconds = 0;  // the fastest of the repeats: the kernel's (CUDA events) or the CPU's wall time
  std::string hash;
  std::string sample_map_hash;  // an adaptive render's: its sample map's pixel hash
};

// An adaptive bundle: the film of render/adaptive_schedule.h's loop on the device asked for.
void render_adaptive_bundle(const SceneBundle& b, const Options& o, const std::string& label, Rendered& r,
                            double& seconds) {
  const SceneView view = view_for(b, o);
  if (o.device == "cuda") {
    GpuAdaptiveFilm g = render_adaptive_on_gpu(b.arrays, view, label);
    seconds = g.run.kernel_seconds;
    r.adaptive = std::move(g.film), r.rays = g.rays;
  } else {
    const auto t = std::chrono::steady_clock::now();
    CpuAdaptiveFilm c = render_adaptive_on_cpu(view, o.threads);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    r.adaptive = std::move(c.film), r.rays = c.rays;
  }
  r.nonfinite = adaptive_nonfinite_samples(*r.adaptive), r.overflow = adaptive_overflow_samples(*r.adaptive);
}

Rendered render_bundle_unguarded(const SceneBundle& b, const Options& o, const std::string& label) {
  const SceneView view = view_for(b, o);
  Rendered r;
  for (uint32_t i = 0; i < o.repeat; ++i) {
    double seconds = 0;
    if (adaptive_render(view.settings)) {
      render_adaptive_bundle(b, o, label, r, seconds);
    } else if (o.device == "cuda") {
      GpuFilm g = render_film_on_gpu(b.arrays, view, b.range, label);
      seconds = g.run.kernel_seconds;
      r.film = std::move(g.film), r.rays = g.rays, r.nonfinite = g.nonfinite, r.overflow = g.overflow;
    } else {
      const auto t = std::chrono::steady_clock::now();
      CpuFilm c = render_film_on_cpu(view, b.range, o.threads);
      seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
      r.film = std::move(c.film), r.rays = c.rays, r.nonfinite = c.nonfinite, r.overflow = c.overflow;
    }
    if (i == 0 || seconds < r.best_seconds) r.best_seconds = seconds;
  }
  // A whole render's image hashes as the golden manifest does; a part's hash is of its film sums.
  if (r.adaptive) {
    r.hash = pixel_hash(resolve_adaptive(*r.adaptive));
    r.sample_map_hash = pixel_hash(adaptive_sample_map(*r.adaptive));
  } else if (b.range.begin == 0 && b.range.end == b.scalars.settings.spp) {
    r.hash = pixel_hash(resolve_film(r.film, b.scalars.settings.spp));
  } else {
    Sha1 sha;
    sha.append(r.film.pixels.data(), r.film.pixels.size() * sizeof(FilmSum));
    r.hash = "sha1-film:" + sha.hex_digest();
  }
  return r;
}

Rendered render_bundle(const SceneBundle& b, const Options& o, const std::string& label) {
  return naming_file_when_out_of_memory(label, "rendering the bundle",
                                        [&] { return render_bundle_unguarded(b, o, label); });
}

void write_film(const std::string& path, const Rendered& r) {
  BundleFile f;
  f.kind = "film";
  f.add("film", r.film.pixels);
  f.add_one("samples", r.film.range);
  f.add("size", std::vector<uint32_t>{r.film.width, r.film.height});
  f.add("hash", std::vector<char>(r.hash.begin(), r.hash.end()));
  write_bundle(path, f);
}

double mrays_per_second(const Rendered& r) {
  const double rays = static_cast<double>(r.rays.camera + r.rays.secondary + r.rays.shadow);
  return r.best_seconds > 0 ? rays / r.best_seconds / 1e6 : 0.0;
}

int run_render(const Options& o) {
  const SceneBundle b = read_scene_bundle(o.input);
  const RenderSettings& rs = b.scalars.settings;
  if (!o.output.empty() && adaptive_render(rs))
    throw InputError("-o " + o.output + ": " + o.input +
                     " is an adaptive render, whose film (half sums and sample counts) is not a film part");
  const Rendered r = render_bundle(b, o, o.input);
  if (!o.output.empty()) write_film(o.output, r);
  if (r.adaptive) std::printf("%s sample map\n", r.sample_map_hash.c_str());
  std::printf("%s %s: %ux%u, samples [%u, %u), %.6f s, %.1f Mrays/s, %llu NaN/inf, %llu overflow\n", r.hash.c_str(),
              o.input.c_str(), rs.width, rs.height, b.range.begin, b.range.end, r.best_seconds, mrays_per_second(r),
              static_cast<unsigned long long>(r.nonfinite), static_cast<unsigned long long>(r.overflow));
  if (!o.expect.empty() && o.expect != r.hash) {
    std::printf("FAIL: expected %s\n", o.expect.c_str());
    return 1;
  }
  return 0;
}

// true when the device's answers equal the CPU answers the pack stored; `detail` says why not.
bool check_parity(const std::string& path, const Options& o, std::string& detail) {
  const parity::StoredParityCase s = parity::read_parity_case(path);
  const parity::ParityAnswers got = parity::evaluate_parity_case(s.parity, o.device == "cuda", o.threads);
  char seconds[64];
  std::snprintf(seconds, sizeof seconds, ", %.6f s", got.seconds);
  detail = std::to_string(got.inputs) + " inputs" + seconds + (got.note.empty() ? "" : ", " + got.note);
  if (got.inputs_sha1 != s.inputs_sha1) {
    detail += "; the inputs generated here differ from the pack's (generator drift): cannot compare";
    return false;
  }
  if (got.answers_sha1 == s.answers_sha1) {
    if (s.parity.spec.kind == parity::ParityKind::Lbvh && o.device == "cuda") {  // the CPU build, timed beside it
      const parity::ParityAnswers cpu = parity::evaluate_parity_case(s.parity, false, o.threads);
      std::snprintf(seconds, sizeof seconds, "; cpu build (%u threads) %.6f s", o.threads, cpu.seconds);
      detail += seconds;
    }
    return true;
  }
  detail += "; answers differ from the CPU's";
  // Recompute the reference here to name the inputs that differ (a Stream case's reference is
  // the megakernel, so its CPU stream can differ from it too).
  if (o.device == "cuda" || s.parity.spec.kind == parity::ParityKind::Stream) {
    const parity::ParityAnswers cpu = parity::reference_parity_answers(s.parity, o.threads);
    detail += cpu.answers_sha1 == s.answers_sha1 ? ":\n" + parity::describe_differences(cpu, got, 5)
                                                 : " (and this machine's CPU differs from the pack's too)";
  }
  return false;
}

int run_parity(const Options& o) {
  std::string detail;
  const bool pass = check_parity(o.input, o, detail);
  std::printf("%s %s: %s\n", pass ? "PASS" : "FAIL", o.input.c_str(), detail.c_str());
  return pass ? 0 : 1;
}

// DIR/pack.tsv: one line per entry, "golden NAME FILE sha1:HASH [SCHEDULE]" (the image's
// hash), "sample-map NAME FILE sha1:HASH [SCHEDULE]" (an adaptive render's sample map) or
// "parity NAME FILE -". SCHEDULE: "megakernel", "stream:WIDTH" or "stream:WIDTH:ORDER" (queue or
// sorted); the bundle's when absent.
int run_pack(const Options& o) {
  const std::string dir = o.input + "/";
  std::istringstream list(read_text_file(dir + "pack.tsv", "pack list", 1u << 20));
  std::string device = "cpu (" + std::to_string(o.threads) + " threads)";
  if (o.device == "cuda") device = parity::gpu_device();
  std::printf("tracer-gpu pack %s on %s\n%-10s %-36s %-5s %s\n", o.input.c_str(), device.c_str(), "kind", "name",
              "result", "detail");
  size_t passed = 0, total = 0;
  for (std::string line; std::getline(list, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string kind, name, file, expected;
    if (!(fields >> kind >> name >> file >> expected)) throw InputError(dir + "pack.tsv: malformed line: " + line);
    std::string schedule;
    fields >> schedule;
    ++total;
    bool pass = false;
    std::string detail;
    try {
      if (kind == "golden" || kind == "sample-map") {
        const SceneBundle b = read_scene_bundle(dir + file);
        const Options ro = schedule.empty() ? o : with_schedule(o, schedule, dir + "pack.tsv: " + name);
        const Rendered r = render_bundle(b, ro, dir + file);
        const std::string& got = kind == "golden" ? r.hash : r.sample_map_hash;
        pass = got == expected;
        // The stream schedule's trace kernels on the GPU (kernel/accel/trace_variants.h), for the
        // tree its upload holds (render/device_bvh.h).
        const SceneView view = view_for(b, ro);
        const std::string trace = view.settings.schedule == Schedule::Stream
                                      ? std::string(", trace ") + trace_variant_name(device_trace_variant(view))
                                      : "";
        char text[160];
        std::snprintf(text, sizeof text, "%.6f s, %.1f Mrays/s%s", r.best_seconds, mrays_per_second(r), trace.c_str());
        detail = pass                             ? text
                 : r.adaptive || kind == "golden" ? "got " + got + ", expected " + expected
                                                  : "a sample map needs an adaptive render; the bundle is uniform";
      } else if (kind == "parity") {
        pass = check_parity(dir + file, o, detail);
      } else {
        detail = "unknown kind " + kind;
      }
    } catch (const std::exception& e) {
      detail = std::string("error: ") + e.what();
    }
    passed += pass;
    std::printf("%-10s %-36s %-5s %s\n", kind.c_str(), name.c_str(), pass ? "PASS" : "FAIL", detail.c_str());
    std::fflush(stdout);
  }
  std::printf("%zu of %zu passed on %s\n", passed, total, device.c_str());
  return passed == total && total > 0 ? 0 : 1;
}

// A rays row's fourth field, "mesh:KIND:TRIANGLES": `b` with that generated mesh (ray_bench.h).
SceneBundle with_mesh_field(const SceneBundle& b, const std::string& field, const std::string& where) {
  const size_t colon = field.find(':', 5);
  try {
    if (colon == std::string::npos) throw InputError(field + ": expected mesh:KIND:TRIANGLES");
    return with_generated_mesh(b, field.substr(5, colon - 5),
                               parse_count(field.substr(0, colon), field.substr(colon + 1), kMostGeneratedTriangles));
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  }
}

// DIR/bench.tsv: "TABLE LABEL FILE [SCHEDULE]" per row (SCHEDULE as in pack.tsv; a row of table "rays" may
// name "mesh:KIND:TRIANGLES" there instead, ray_bench.h). Each bundle is rendered --repeat
// times on the device and its best time reported; on the GPU the CPU renders it once beside it, as the baseline of the
// same run. Rows of table "rays" trace ray sets instead (ray_bench.h).
int run_bench(const Options& o) {
  const std::string dir = o.input + "/";
  std::istringstream list(read_text_file(dir + "bench.tsv", "bench list", 1u << 20));
  const bool gpu = o.device == "cuda";
  std::printf("tracer-gpu bench %s on %s, best of %u; the CPU baseline: %u threads, one frame\n", o.input.c_str(),
              gpu ? parity::gpu_device().c_str() : "cpu", o.repeat, o.threads);
  std::printf("%-10s %-34s %10s %10s %10s %12s %9s\n", "table", "label", "s/frame", "frames/s", "Mrays/s",
              gpu ? "CPU s/frame" : "", gpu ? "speed-up" : "");
  Options cpu = o;
  cpu.device = "cpu", cpu.repeat = 1;
  bool rays_header = false;
  for (std::string line; std::getline(list, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string table, label, file, schedule;
    if (!(fields >> table >> label >> file)) throw InputError(dir + "bench.tsv: malformed line: " + line);
    fields >> schedule;
    if (table == "rays") {
      if (!rays_header)
        std::printf("%-10s %-34s %10s %10s %10s  %s\n", "table", "label", "primary", "incoherent", "shadow",
                    "hits (checksum), Mrays/s");
      rays_header = true;
      const SceneBundle b = read_scene_bundle(dir + file);
      run_ray_bench(schedule.rfind("mesh:", 0) == 0 ? with_mesh_field(b, schedule, dir + "bench.tsv: " + label) : b,
                    label, gpu, o.threads, o.repeat);
      continue;
    }
    const Options row = schedule.empty() ? o : with_schedule(o, schedule, dir + "bench.tsv: " + label);
    const SceneBundle b = read_scene_bundle(dir + file);
    const Rendered r = render_bundle(b, row, dir + file);
    std::printf("%-10s %-34s %10.6f %10.1f %10.1f", table.c_str(), label.c_str(), r.best_seconds,
                r.best_seconds > 0 ? 1.0 / r.best_seconds : 0.0, mrays_per_second(r));
    if (gpu) {
      const Rendered base = render_bundle(b, cpu, dir + file);
      std::printf(" %12.6f %8.1fx%s", base.best_seconds, base.best_seconds / r.best_seconds,
                  base.hash == r.hash ? "" : "  (image differs from the CPU's)");
    }
    std::printf("\n");
    std::fflush(stdout);
  }
  return 0;
}

int run_command(int argc, char** argv) {
  try {
    const Options o = parse(argc, argv);
    if (o.command == "render") return run_render(o);
    if (o.command == "parity") return run_parity(o);
    if (o.command == "pack") return run_pack(o);
    if (o.command == "bench") return run_bench(o);
    if (o.command == "device") {
      std::printf("%s\n%s\n%s\n", parity::gpu_device().c_str(), describe_render_kernel().c_str(),
                  describe_stream_kernels().c_str());
      return 0;
    }
    throw InputError(o.command + ": unknown command\n" + kUsage);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
}

}  // namespace
}  // namespace tracer

int main(int argc, char** argv) { return tracer::exit_code_after_flushing_stdout(tracer::run_command(argc, argv)); }
