// CPU/GPU parity of the kernel entry points, compared as bits over large sweeps: the
// deterministic math functions, Philox, the ray/shape tests, BVH traversal and whole
// pixels. Each test computes the CPU side first (and checks it where it can); without a
// usable GPU it then reports SKIPPED with the reason, never PASSED.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>

#include "golden/golden_manifest.h"
#include "parity/parity_gpu.h"
#include "parity/parity_inputs.h"
#include "render/device_error.h"
#include "render/render_cpu.h"
#include "scene/scene_loader.h"
#include "test_util.h"

namespace tracer::parity {
namespace {

// Skips the rest of a test, with the reason, when no GPU can run it.
#define SKIP_WITHOUT_GPU()                                                       \
  do {                                                                           \
    try {                                                                        \
      std::printf("GPU: %s\n", gpu_device().c_str());                            \
    } catch (const DeviceUnavailable& e) {                                       \
      GTEST_SKIP() << "CPU side computed; no GPU to compare with: " << e.what(); \
    }                                                                            \
  } while (0)

// Counts elements whose bytes differ and reports the first few with their index.
template <class T, class Describe>
void expect_same_bits(const std::vector<T>& cpu, const std::vector<T>& gpu, Describe describe) {
  ASSERT_EQ(cpu.size(), gpu.size());
  size_t mismatches = 0;
  for (size_t i = 0; i < cpu.size(); ++i) {
    if (std::memcmp(&cpu[i], &gpu[i], sizeof(T)) == 0) continue;
    if (++mismatches <= 5) ADD_FAILURE() << "CPU and GPU differ at input " << i << ": " << describe(i);
  }
  EXPECT_EQ(mismatches, 0u) << "of " << cpu.size() << " inputs";
}

std::string hex(float f) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a (0x%08x)", static_cast<double>(f), bits_of(f));
  return buf;
}

TEST(CudaParity, DeterministicMathFunctions) {
  // Per function: every pair of edge values, 2^20 random bit patterns, 2^19 points of its domain.
  std::vector<float> a[kMathFunctionCount], b[kMathFunctionCount], cpu[kMathFunctionCount];
  for (uint32_t fi = 0; fi < kMathFunctionCount; ++fi) {
    MathInputs in = math_inputs(static_cast<MathFunction>(fi), fi, 1u << 20, 1u << 19);
    a[fi] = std::move(in.a), b[fi] = std::move(in.b);
    for (size_t i = 0; i < a[fi].size(); ++i)
      cpu[fi].push_back(eval_math(static_cast<MathFunction>(fi), a[fi][i], b[fi][i]));
  }
  SKIP_WITHOUT_GPU();
  for (uint32_t fi = 0; fi < kMathFunctionCount; ++fi) {
    SCOPED_TRACE("function " + std::to_string(fi));
    expect_same_bits(cpu[fi], gpu_math(static_cast<MathFunction>(fi), a[fi], b[fi]),
                     [&](size_t i) { return "f(" + hex(a[fi][i]) + ", " + hex(b[fi][i]) + ")"; });
  }
}

TEST(CudaParity, Philox) {
  const std::vector<PhiloxQuery> q = philox_inputs(7, 1u << 21);
  std::vector<Philox4> cpu(q.size());
  for (size_t i = 0; i < q.size(); ++i) cpu[i] = eval_philox(q[i]);
  SKIP_WITHOUT_GPU();
  expect_same_bits(cpu, gpu_philox(q), [](size_t i) { return std::to_string(i); });
}

TEST(CudaParity, RayShapeTests) {
  const std::vector<ShapeQuery> q = shape_inputs(11, 1u << 20);
  std::vector<ShapeAnswer> cpu(q.size());
  size_t hits = 0;
  for (size_t i = 0; i < q.size(); ++i) hits += (cpu[i] = eval_shape(q[i])).hit;
  EXPECT_GT(hits, q.size() / 3) << "the queries should mostly hit";
  SKIP_WITHOUT_GPU();
  expect_same_bits(cpu, gpu_shapes(q), [&](size_t i) {
    return "kind " + std::to_string(static_cast<int>(q[i].prim.kind)) + ", t " + hex(cpu[i].t);
  });
}

Scene golden_scene(const std::string& name) {
  const GoldenManifest manifest = read_manifest(TRACER_SOURCE_DIR);
  const GoldenEntry& e = manifest.find(name);
  return load_scene(manifest.scene_path(e), RenderOverrides{e.options});
}

// 2^20 rays per scene, origins uniform in its bounds, directions uniform on the sphere.
TEST(CudaParity, BvhTraversal) {
  const char* names[] = {"cornell-box", "mesh", "refraction"};
  std::vector<Scene> scenes;
  std::vector<std::vector<Ray>> rays(3);
  std::vector<std::vector<TraceAnswer>> cpu(3);
  for (int s = 0; s < 3; ++s) {
    scenes.push_back(golden_scene(names[s]));
    const SceneView view = scenes[s].view();
    const BvhNode& root = scenes[s].bvh_nodes.at(0);
    rays[s] = ray_inputs(13, 1u << 20, root.lo, root.hi);
    size_t hits = 0;
    for (const Ray& r : rays[s]) {
      cpu[s].push_back(eval_trace(view, r));
      hits += cpu[s].back().closest.prim != kNoHit;
    }
    EXPECT_GT(hits, rays[s].size() / 4) << names[s];
  }
  SKIP_WITHOUT_GPU();
  for (int s = 0; s < 3; ++s) {
    SCOPED_TRACE(names[s]);
    expect_same_bits(cpu[s], gpu_trace(scenes[s], scenes[s].view(), rays[s]), [&](size_t i) {
      return "t " + hex(cpu[s][i].closest.t) + ", prim " + std::to_string(cpu[s][i].closest.prim);
    });
  }
}

TEST(CudaParity, AdaptiveSamplingDecisions) {
  const std::vector<AdaptiveQuery> q = adaptive_inputs(19, 1u << 20);
  std::vector<AdaptiveAnswer> cpu(q.size());
  size_t unconverged = 0, zero_error = 0, infinite_error = 0;
  for (size_t i = 0; i < q.size(); ++i) {
    cpu[i] = eval_adaptive(q[i]);
    unconverged += cpu[i].unconverged;
    zero_error += cpu[i].relative_error == 0.0;
    infinite_error += std::isinf(cpu[i].relative_error);
    ASSERT_EQ(cpu[i].unconverged,
              q[i].threshold == 0.0f || !(cpu[i].relative_error < static_cast<double>(q[i].threshold)))
        << "input " << i;
  }
  // Both answers and the estimate's special values are among the inputs.
  EXPECT_GT(unconverged, q.size() / 8);
  EXPECT_LT(unconverged, q.size() - q.size() / 8);
  EXPECT_GE(zero_error, q.size() / 8) << "the all-zero pixels";
  EXPECT_GT(infinite_error, 0u) << "the pixels whose mean is 0 or less but whose halves differ";
  SKIP_WITHOUT_GPU();
  expect_same_bits(cpu, gpu_adaptive(q), [&](size_t i) {
    char text[96];
    std::snprintf(text, sizeof text, "error %a, unconverged %u", cpu[i].relative_error, cpu[i].unconverged);
    return std::string(text);
  });
}

// Sampling and evaluating the microfacet materials. The CPU side also checks every answer
// is a number (a NaN here would reach the film) and that every kind samples.
TEST(CudaParity, MicrofacetBsdfs) {
  const std::vector<BsdfQuery> q = bsdf_inputs(23, 1u << 20);
  std::vector<BsdfAnswer> cpu(q.size());
  size_t sampled[3] = {}, specular = 0;
  for (size_t i = 0; i < q.size(); ++i) {
    const BsdfAnswer& a = cpu[i] = eval_bsdf_case(q[i]);
    const float values[] = {a.wi.x, a.wi.y, a.wi.z, a.weight.x, a.weight.y, a.weight.z, a.pdf, a.f_cos.x, a.f_cos.y,
                            a.f_cos.z, a.eval_pdf, a.f_cos_other.x, a.f_cos_other.y, a.f_cos_other.z, a.pdf_other};
    for (float v : values) ASSERT_TRUE(std::isfinite(v)) << "input " << i << ": " << hex(v);
    sampled[i % 3] += a.sampled;
    specular += a.specular;
  }
  for (size_t kind = 0; kind < 3; ++kind) EXPECT_GT(sampled[kind], q.size() / 6) << "material kind " << kind;
  EXPECT_GT(specular, q.size() / 100) << "the smooth conductor and glass";
  SKIP_WITHOUT_GPU();
  expect_same_bits(cpu, gpu_bsdfs(q), [&](size_t i) {
    return "kind " + std::to_string(static_cast<int>(q[i].m.kind)) + ", pdf " + hex(cpu[i].pdf);
  });
}

TEST(CudaParity, WholePixelsOfEveryGolden) {
  const GoldenManifest manifest = read_manifest(TRACER_SOURCE_DIR);
  std::vector<Scene> scenes;
  std::vector<std::vector<SampleAnswer>> cpu;
  for (const GoldenEntry& e : manifest.entries) {
    SCOPED_TRACE(e.name);
    scenes.push_back(load_scene(manifest.scene_path(e), RenderOverrides{e.options}));
    const SceneView view = scenes.back().view();
    const size_t n = static_cast<size_t>(view.settings.width) * view.settings.height;
    cpu.emplace_back(n);
    for (size_t i = 0; i < n; ++i) cpu.back()[i] = eval_sample(view, static_cast<uint32_t>(i));
    // The CPU side equals the CPU renderer, so the GPU is compared with what the goldens hold.
    RenderStats stats;
    const FilmBuffer film = render_cpu_film(scenes.back(), {0, view.settings.spp}, 1, stats);
    for (size_t i = 0; i < n; ++i)
      ASSERT_EQ(std::memcmp(&cpu.back()[i].pixel, &film.pixels[i], sizeof(FilmSum)), 0) << "pixel " << i;
  }
  SKIP_WITHOUT_GPU();
  for (size_t g = 0; g < scenes.size(); ++g) {
    SCOPED_TRACE(manifest.entries[g].name);
    expect_same_bits(cpu[g], gpu_samples(scenes[g], scenes[g].view()),
                     [](size_t i) { return "pixel " + std::to_string(i); });
  }
}

TEST(CudaParity, RenderThroughTheCli) {
  const auto dir = test::temp_dir("cuda-cli");
  const std::string scene = test::source_path("scenes/features/refraction.json");
  const std::string cpu = (dir / "cpu.exr").string(), gpu = (dir / "gpu.exr").string();
  std::string output;
  ASSERT_EQ(test::run_tracer("render " + scene + " --quiet -o " + cpu, &output), 0) << output;
  const int code = test::run_tracer("render " + scene + " --quiet --device cuda -o " + gpu, &output);
  bool have_gpu = true;
  try {
    gpu_device();
  } catch (const DeviceUnavailable&) {
    have_gpu = false;
  }
  if (!have_gpu) {
    EXPECT_EQ(code, 2) << output;
    EXPECT_NE(output.find("error: "), std::string::npos) << output;
    EXPECT_NE(output.find("CUDA"), std::string::npos) << output;
    EXPECT_FALSE(std::filesystem::exists(gpu)) << "no output without a GPU";
  } else {
    ASSERT_EQ(code, 0) << output;
    EXPECT_EQ(test::run_tracer("compare " + cpu + " " + gpu + " --fail 0", &output), 0) << output;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tracer::parity
