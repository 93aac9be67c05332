// The resource audit's parts (docs/cuda.md, "Resource budgets"): ptxas' report parsed kernel by
// kernel, readable kernel names, the occupancy rules of sm_90 against the figures the H100's
// profiler gave, and the budget check's verdicts.
#include <gtest/gtest.h>

#include <limits>

#include "audit/kernel_budgets.h"
#include "audit/kernel_resources.h"

namespace tracer {
namespace {

constexpr const char* kStage1 =
    "_ZN6tracer46_GLOBAL__N__00284fd8_13_gpu_stream_cu_a68627a412stage_kernelILNS_11StreamStageE1EEEvNS_"
    "9SceneViewENS_12StreamStatesEPKjmPy";
constexpr const char* kRender =
    "_ZN6tracer44_GLOBAL__N__a1b5451b_11_gpu_film_cu_9deb804b13render_kernelENS_9SceneViewENS_11SampleRangeEPNS_"
    "7FilmSumEPy";

TEST(KernelResources, ParsesPtxasReportPerKernelAndArchitecture) {
  const std::string report = std::string("ptxas info    : 0 bytes gmem\n") +
                             "ptxas info    : Compiling entry function '" + kRender + "' for 'sm_80'\n" +
                             "ptxas info    : Function properties for " + kRender + "\n" +
                             "    2900 bytes stack frame, 8 bytes spill stores, 4 bytes spill loads\n" +
                             "ptxas info    : Used 190 registers, used 0 barriers, 2900 bytes cumulative stack size\n" +
                             "ptxas info    : Compiling entry function '" + kStage1 + "' for 'sm_90'\n" +
                             "ptxas info    : Function properties for _Z6helperv\n" +
                             "    48 bytes stack frame, 0 bytes spill stores, 0 bytes spill loads\n" +
                             "ptxas info    : Function properties for " + kStage1 + "\n" +
                             "    272 bytes stack frame, 0 bytes spill stores, 0 bytes spill loads\n" +
                             "ptxas info    : Used 72 registers, used 1 barriers, 1024 bytes smem, 560 bytes cmem[0]\n";
  const std::vector<KernelResources> k = parse_resource_report(report);
  ASSERT_EQ(k.size(), 2u);
  EXPECT_EQ(k[0].arch, "sm_80");
  EXPECT_EQ(k[0].name, "render_kernel");
  EXPECT_EQ(k[0].registers, 190);
  EXPECT_EQ(k[0].stack_bytes, 2900);
  EXPECT_EQ(k[0].spill_stores, 8);
  EXPECT_EQ(k[0].spill_loads, 4);
  EXPECT_EQ(k[1].arch, "sm_90");
  EXPECT_EQ(k[1].name, "stage_kernel<(tracer::StreamStage)1>");
  EXPECT_EQ(k[1].stack_bytes, 272);  // its own frame, not the helper's
  EXPECT_EQ(k[1].registers, 72);
  EXPECT_EQ(k[1].shared_bytes, 1024);
}

TEST(KernelResources, LibraryKernelsHaveNoName) {
  EXPECT_EQ(kernel_name("_ZN3cub17CUB_300001_SM_9006detail11EmptyKernelIvEEvv"), "");
  EXPECT_EQ(kernel_name(kRender), "render_kernel");
}

// The occupancies the H100's profiler reported (docs/cuda.md, "Runs on a GPU"): the megakernel's
// 166 registers in blocks of 256, the stream stages' 26 / 72 / 90 registers in blocks of 128.
TEST(KernelResources, Sm90OccupancyMatchesTheProfiler) {
  EXPECT_DOUBLE_EQ(sm90_occupancy(166, 256, 0), 0.125);
  EXPECT_DOUBLE_EQ(sm90_occupancy(26, 128, 0), 1.0);
  EXPECT_DOUBLE_EQ(sm90_occupancy(72, 128, 0), 0.4375);
  EXPECT_DOUBLE_EQ(sm90_occupancy(90, 128, 0), 0.3125);
  EXPECT_DOUBLE_EQ(sm90_occupancy(32, 128, 100 * 1024), 2 * 4 / 64.0);  // shared memory: 2 blocks
}

TEST(KernelResources, EveryKernelWithinItsRowPassesAndEachExcessIsNamed) {
  std::vector<KernelResources> kernels;
  for (const KernelBudget& b : kKernelBudgets) {
    KernelResources k;
    k.arch = "sm_90";
    k.name = b.kernel;
    k.registers = b.registers;
    k.stack_bytes = b.stack_bytes;
    k.spill_stores = k.spill_loads = b.spill_bytes;
    k.shared_bytes = b.shared_bytes;
    k.used_line = true;
    kernels.push_back(k);
  }
  KernelResources library = kernels[0];
  library.name = "";  // CUB's: not budgeted
  library.registers = 255;
  kernels.push_back(library);
  EXPECT_TRUE(budget_problems(kernels).empty());
  kernels[0].registers += 1;
  std::vector<std::string> p = budget_problems(kernels);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find(std::string(kKernelBudgets[0].kernel) + ": " + std::to_string(kKernelBudgets[0].registers + 1) +
                      " registers, over its budget"),
            std::string::npos)
      << p[0];
  kernels[0].registers -= 1;
  kernels.push_back(kernels[0]);
  kernels.back().name = "new_kernel";
  p = budget_problems(kernels);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("new_kernel: no row"), std::string::npos) << p[0];
  kernels.erase(kernels.begin());
  kernels.pop_back();
  p = budget_problems(kernels);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("no sm_90 kernel of the build matches"), std::string::npos) << p[0];
}

// A report edited or garbled: a figure past int's range read as 0 and passed (4294967296
// registers), one past what a thread holds overflowed the occupancy arithmetic (SIGFPE), a
// kernel without its "Used" line passed with 0 registers. Each is a named problem now.
TEST(KernelResources, AReportThatCannotBeTrustedIsAProblem) {
  const KernelBudget& row = kKernelBudgets[0];
  const std::string mangled = kRender;
  const auto report = [&](const std::string& used) {
    return "ptxas info    : Compiling entry function '" + mangled + "' for 'sm_90'\n" +
           "ptxas info    : Function properties for " + mangled + "\n" +
           "    0 bytes stack frame, 0 bytes spill stores, 0 bytes spill loads\n" + used;
  };
  const struct {
    std::string used, expected;
  } cases[] = {
      {"ptxas info    : Used 4294967296 registers, used 0 barriers\n", "not a number an int holds"},
      {"ptxas info    : Used 134217728 registers, used 0 barriers\n", "134217728 registers, more than an sm_90"},
      {"ptxas info    : Used 256 registers, used 0 barriers\n", "256 registers, more than an sm_90"},
      {"ptxas info    : Used 40 registers, 99999999999 bytes smem\n", "shared memory bytes that is not a number"},
      {"", "has no \"Used ... registers\" line"},
  };
  for (const auto& c : cases) {
    std::vector<KernelResources> k = parse_resource_report(report(c.used));
    ASSERT_EQ(k.size(), 1u);
    k[0].name = row.kernel;  // as if it were the row's kernel, so only the report's figures matter
    EXPECT_EQ(sm90_occupancy(k[0].registers, row.block, k[0].shared_bytes) >= 0.0, true);
    const std::vector<std::string> problems = budget_problems(k);
    bool named = false;
    for (const std::string& p : problems) named = named || p.find(c.expected) != std::string::npos;
    EXPECT_TRUE(named) << c.used << (problems.empty() ? "(no problem)" : problems[0]);
  }
  EXPECT_EQ(sm90_occupancy(134217728, 256, 0), 0.0);
  EXPECT_EQ(sm90_occupancy(std::numeric_limits<int>::max(), 256, std::numeric_limits<int>::max()), 0.0);
}

}  // namespace
}  // namespace tracer
