// `tracer golden check | update | report | list`: the golden-image workflow (docs/golden.md).
#include <cstdio>
#include <filesystem>

#include "cli/command_registry.h"
#include "cli/commands.h"
#include "golden/golden_check.h"
#include "golden/golden_lock.h"
#include "golden/golden_report.h"
#include "golden/golden_update.h"
#include "io/input_error.h"
#include "render/device_error.h"

namespace tracer {

// `golden check`'s exit code when the device is not on this machine (CTest's SKIP_RETURN_CODE).
constexpr int kExitSkipped = 77;

struct GoldenCheckCommand {
  std::string name, root = ".", report, device = "cpu";
  int threads = 0;
};
struct GoldenReportCommand {
  std::string report;
  bool reset = false;
};
namespace {

void print_row(const char* name, const char* status, const std::string& differing, const std::string& max_error,
               const std::string& rms, const std::string& psnr) {
  std::printf("%-28s %-10s %16s %12s %12s %10s\n", name, status, differing.c_str(), max_error.c_str(), rms.c_str(),
              psnr.c_str());
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

}  // namespace

static int run_golden_check(const GoldenCheckCommand& cmd) {
  GoldenManifest manifest;
  manifest.root = cmd.root;
  manifest.path = manifest_path(cmd.root);
  GoldenEntry entry;
  entry.name = cmd.name;
  entry.scene = "(unknown)";
  GoldenOutcome outcome;
  std::optional<GoldenRender> render;
  if (!cmd.report.empty()) prepare_report_dir(cmd.report);  // before the render it would report
  try {
    const GoldenLock lock(cmd.root, GoldenAccess::Read);  // held until the reference is read
    manifest = read_manifest(cmd.root);
    entry = manifest.find(cmd.name);
    if (cmd.device != "cpu" && cmd.device != "cuda")
      throw InputError("--device " + cmd.device + ": expected cpu or cuda");
    const GoldenDevice device = cmd.device == "cuda" ? GoldenDevice::Cuda : GoldenDevice::Cpu;
    render = render_golden(manifest, entry, cmd.threads, device);
    outcome = judge_golden(manifest, entry, *render);
  } catch (const DeviceUnavailable& e) {
    outcome = golden_error(entry, std::string("skipped: ") + e.what(), GoldenStatus::Skipped);
  } catch (const InputError& e) {
    outcome = golden_error(entry, e.what());
  }
  if (!cmd.report.empty()) {  // the row, and the page of every row so far: the report opens after any check
    write_report_row(cmd.report, manifest, entry, render ? &*render : nullptr, outcome);
    assemble_report(cmd.report);
  }
  const char* verdicts[] = {"PASS", "FAIL", "ERROR", "SKIPPED"};
  const char* verdict = verdicts[static_cast<int>(outcome.status)];
  // The verdict goes to stdout, except an error, which goes to stderr as every command's errors do.
  std::fprintf(outcome.status == GoldenStatus::Error ? stderr : stdout, "golden %s: %s: %s\n", cmd.name.c_str(),
               verdict, outcome.message.c_str());
  if (outcome.status == GoldenStatus::Skipped) return kExitSkipped;
  if (outcome.status != GoldenStatus::Pass) {
    if (!cmd.report.empty())
      std::printf("report: %s\n", (std::filesystem::absolute(cmd.report) / "index.html").string().c_str());
    if (outcome.status == GoldenStatus::Fail)
      std::printf("to accept the new image: %s\n", update_command(manifest, cmd.name).c_str());
  }
  return outcome.status == GoldenStatus::Pass ? 0 : outcome.status == GoldenStatus::Fail ? 1 : 2;
}

static int run_golden_update(const UpdateRequest& request) {
  const std::vector<GoldenChange> changes = update_goldens(request);
  int changed = 0;
  print_row("golden", "status", "pixels differing", "max error", "RMS error", "PSNR dB");
  for (const GoldenChange& c : changes) {
    if (c.kind == GoldenChangeKind::Unchanged) continue;
    ++changed;
    if (c.metrics && c.metrics->same_size)
      print_row(c.name.c_str(), change_name(c.kind),
                std::to_string(c.metrics->pixels_not_identical) + "/" + std::to_string(c.metrics->pixels),
                number(c.metrics->max_error), number(c.metrics->rms_error), number(c.metrics->psnr));
    else
      print_row(c.name.c_str(), change_name(c.kind), c.metrics ? "size differs" : "-", "-", "-", "-");
  }
  std::printf("%d of %zu matching goldens rewritten, %zu unchanged%s\n", changed, changes.size(),
              changes.size() - changed, changed ? "; commit golden/ and say why the images changed" : "");
  return 0;
}

static int run_golden_report(const GoldenReportCommand& cmd) {
  if (cmd.reset) {
    reset_report(cmd.report);
    return 0;
  }
  const ReportCounts counts = assemble_report(cmd.report);
  std::printf("golden report: %s (%d differ, %d could not be checked, %d skipped, %d identical)\n",
              (std::filesystem::absolute(cmd.report) / "index.html").string().c_str(), counts.failed, counts.errors,
              counts.skipped, counts.passed);
  return 0;
}

static int run_golden_list(const std::string& root) {
  const GoldenLock lock(root, GoldenAccess::Read);
  for (const GoldenEntry& e : read_manifest(root).entries) std::printf("%s\n", e.name.c_str());
  return 0;
}

const RegisterCommand kGoldenCheckCommand(
    {"golden", "check", "render one golden and compare it bit for bit with its reference", [](CLI::App& app) {
       auto cmd = std::make_shared<GoldenCheckCommand>();
       app.add_option("name", cmd->name, "golden name (golden/manifest.json)")->required();
       app.add_option("--root", cmd->root, "source root holding golden/ and scenes/ (default .)");
       app.add_option("--report", cmd->report, "report directory: writes a row, and images on a difference");
       add_threads_option(app, cmd->threads);
       app.add_option("--device", cmd->device, "cpu or cuda; exit 77 (skipped) when the device is missing");
       return [cmd] { return run_golden_check(*cmd); };
     }});

const RegisterCommand kGoldenUpdateCommand(
    {"golden", "update", "rewrite the goldens that are new or differ, print what changed", [](CLI::App& app) {
       auto request = std::make_shared<UpdateRequest>();
       app.add_option("--root", request->root, "source root holding golden/ and scenes/ (default .)");
       app.add_option("--filter", request->filter, "only goldens whose name matches this regular expression");
       app.add_flag("--force", request->force, "run even when golden/ has uncommitted edits");
       add_threads_option(app, request->threads);
       return [request] { return run_golden_update(*request); };
     }});

const RegisterCommand kGoldenReportCommand({"golden", "report",
                                            "assemble the HTML report from the rows the checks wrote",
                                            [](CLI::App& app) {
                                              auto cmd = std::make_shared<GoldenReportCommand>();
                                              app.add_option("--report", cmd->report, "report directory")->required();
                                              app.add_flag("--reset", cmd->reset, "remove all rows and images instead");
                                              return [cmd] { return run_golden_report(*cmd); };
                                            }});

const RegisterCommand kGoldenListCommand({"golden", "list", "print the golden names, one per line", [](CLI::App& app) {
                                            auto root = std::make_shared<std::string>(".");
                                            app.add_option("--root", *root, "source root holding golden/ (default .)");
                                            return [root] { return run_golden_list(*root); };
                                          }});

}  // namespace tracer
