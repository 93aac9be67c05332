#include "golden/golden_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "image/image_io.h"
#include "io/input_error.h"
#include "io/json_reader.h"
#include "io/output_batch.h"
#include "io/shell.h"
#include "io/text_file.h"

namespace fs = std::filesystem;

namespace tracer {
namespace {

std::string status_name(GoldenStatus s) {
  switch (s) {
    case GoldenStatus::Pass: return "pass";
    case GoldenStatus::Fail: return "fail";
    case GoldenStatus::Error: return "error";
    case GoldenStatus::Skipped: return "skipped";
  }
  return "error";
}

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// "integrator whitted, sampler grid, spp 4, ...": every recorded option, in table order.
std::string options_summary(const RenderOptions& o) {
  const nlohmann::ordered_json options = o.to_json();
  std::string out;
  for (const auto& [key, value] : options.items())
    out += (out.empty() ? "" : ", ") + key + " " + (value.is_string() ? value.get<std::string>() : value.dump());
  return out;
}

std::string format_scale(double scale) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", scale);
  return buf;
}

std::string metric_cell(const Json& row) {
  const Json& m = row["metrics"];
  if (m.is_null()) return "";
  std::ostringstream s;
  s << "<table class=\"metrics\">"
    << "<tr><th>pixels not bit-identical</th><td>" << m["not_identical"].get<uint64_t>() << " of "
    << m["pixels"].get<uint64_t>() << "</td></tr>"
    << "<tr><th>max error</th><td>" << m["max_error"].get<double>() << " at (" << m["max_x"].get<int>() << ", "
    << m["max_y"].get<int>() << ")</td></tr>"
    << "<tr><th>mean error</th><td>" << m["mean_error"].get<double>() << "</td></tr>"
    << "<tr><th>RMS error</th><td>" << m["rms_error"].get<double>() << "</td></tr>"
    << "<tr><th>PSNR</th><td>" << m["psnr"].get<double>() << " dB</td></tr>"
    << "<tr><th>NaN/inf</th><td>" << row["nonfinite"].get<uint64_t>() << "</td></tr></table>";
  return s.str();
}

std::string image_cell(const Json& row, const char* key, const std::string& caption) {
  const Json& images = row["images"];
  if (!images.contains(key)) return "<figure class=\"image missing\">no " + caption + "</figure>";
  const std::string src = html_escape(images[key].get<std::string>());
  return "<figure class=\"image\"><a href=\"" + src + "\"><img src=\"" + src + "\" alt=\"" + caption +
         "\"></a><figcaption>" + caption + "</figcaption></figure>";
}

// The view image-diff tools have: one image that shows the new image and, while the pointer
// is over it (or after a click, until the next), the reference, at a whole-pixel zoom.
std::string flip_cell(const Json& row) {
  const Json& images = row["images"];
  if (!images.contains("new") || !images.contains("reference")) return "";
  const std::string fresh = html_escape(images["new"].get<std::string>()),
                    reference = html_escape(images["reference"].get<std::string>());
  return "<figure class=\"image flip\"><img class=\"flip\" src=\"" + fresh + "\" data-new=\"" + fresh +
         "\" data-reference=\"" + reference +
         "\" data-showing=\"new\" alt=\"new, reference on hover or click\"><figcaption>flip: new; hover or click for "
         "the reference</figcaption></figure>";
}

std::string row_html(const Json& row) {
  const std::string status = row["status"].get<std::string>();
  std::ostringstream s;
  s << "<tr class=\"" << status << "\" id=\"" << html_escape(row["name"].get<std::string>()) << "\">"
    << "<td class=\"name\"><b>" << html_escape(row["name"].get<std::string>()) << "</b><br><span class=\"badge\">"
    << status << "</span><br><small>" << html_escape(row["scene"].get<std::string>()) << "<br>"
    << html_escape(row["options"].get<std::string>()) << "</small></td>";
  if (status == "pass" || status == "skipped") {
    s << "<td colspan=\"2\" class=\"message\">" << html_escape(row["message"].get<std::string>());
    if (status == "pass") s << " in " << row["seconds"].get<double>() << " s";
    s << "</td>";
  } else {
    const double scale = row["amplification"].get<double>();
    // The images wrap inside their cell, so that a narrow window keeps the metrics in view.
    s << "<td><div class=\"images\">" << flip_cell(row) << image_cell(row, "new", "new")
      << image_cell(row, "reference", "reference")
      << image_cell(row, "difference", scale > 0 ? "difference &times; " + format_scale(scale) : "difference")
      << "</div></td><td class=\"message\"><p>" << html_escape(row["message"].get<std::string>()) << "</p>" << metric_cell(row);
    if (status == "fail")
      s << "<p>To accept the new image as the golden:</p><pre><code>" << html_escape(row["update"].get<std::string>())
        << "</code></pre>";
    s << "</td>";
  }
  s << "</tr>\n";
  return s.str();
}

constexpr const char* kStyle = R"(body{font-family:sans-serif;margin:1.5em;background:#fafafa;color:#222}
table.report{border-collapse:collapse;width:100%}
table.report>tbody>tr>td{border-top:1px solid #ccc;padding:.5em;vertical-align:top}
tr.fail .badge,tr.error .badge{background:#c62828;color:#fff}tr.pass .badge{background:#2e7d32;color:#fff}
tr.skipped .badge{background:#757575;color:#fff}
.badge{padding:0 .4em;border-radius:.3em;text-transform:uppercase;font-size:.8em}
div.images{display:flex;flex-wrap:wrap;gap:.5em}figure.image{margin:0}
figure.image img{width:256px;image-rendering:pixelated;border:1px solid #999;background:#000}
figure.image img.flip{width:auto;cursor:pointer}
figure.image figcaption{font-size:.8em;color:#555}td.message{font-size:.9em;min-width:14em}
table.metrics th{text-align:left;font-weight:normal;color:#555;padding-right:1em}
pre{background:#eee;padding:.4em;white-space:pre-wrap;word-break:break-all}
#broken{color:#c62828;font-weight:bold})";

// Marks the page with the number of images that failed to load and the width its layout
// takes, for people and for the headless-browser test that opens the report. Sizes each flip view to the largest whole
// multiple of its image's width up to 512 pixels (nearest-neighbour, so pixels stay square
// blocks) and wires it: the reference while the pointer is over it, a click pins the other
// image; index.html#show=reference opens every flip view on its reference.
constexpr const char* kScript = R"(<script>
function showFlip(img, which) {
  img.setAttribute('data-showing', which);
  img.src = img.getAttribute(which === 'reference' ? 'data-reference' : 'data-new');
}
window.addEventListener('load', function () {
  var broken = Array.prototype.filter.call(document.images, function (i) { return !i.complete || i.naturalWidth === 0; });
  document.body.setAttribute('data-broken-images', String(broken.length));
  document.body.setAttribute('data-page-width', String(document.documentElement.scrollWidth));
  if (broken.length) { var p = document.getElementById('broken'); p.hidden = false; p.textContent = broken.length + ' image(s) failed to load'; }
  Array.prototype.forEach.call(document.querySelectorAll('img.flip'), function (img) {
    var zoom = Math.max(1, Math.floor(512 / img.naturalWidth));
    img.style.width = (img.naturalWidth * zoom) + 'px';
    img.setAttribute('data-zoom', String(zoom));
    var pinned = 'new';
    img.addEventListener('mouseenter', function () { showFlip(img, pinned === 'new' ? 'reference' : 'new'); });
    img.addEventListener('mouseleave', function () { showFlip(img, pinned); });
    img.addEventListener('click', function () { pinned = pinned === 'new' ? 'reference' : 'new'; showFlip(img, pinned); });
    if (location.hash === '#show=reference') { pinned = 'reference'; showFlip(img, 'reference'); }
  });
});
</script>)";

}  // namespace

float amplified_difference(const Image& fresh, const Image& reference, Image& out) {
  out = fresh;
  float largest = 0.0f;
  for (size_t i = 0; i < fresh.rgb.size(); ++i) {
    const float d = std::abs(fresh.rgb[i] - reference.rgb[i]);
    if (std::isfinite(d)) largest = std::max(largest, d);
  }
  const float scale = largest > 0.0f ? 1.0f / largest : 0.0f;
  for (size_t p = 0; p < fresh.rgb.size(); p += 3) {
    bool nonfinite = false;
    for (int c = 0; c < 3; ++c) nonfinite |= !std::isfinite(fresh.rgb[p + c]);
    for (int c = 0; c < 3; ++c)
      out.rgb[p + c] = nonfinite ? (c == 1 ? 0.0f : 1.0f) : std::abs(fresh.rgb[p + c] - reference.rgb[p + c]) * scale;
  }
  return scale;
}

std::string update_command(const GoldenManifest& manifest, const std::string& name) {
  std::error_code ec;
  const fs::path binary = fs::read_symlink("/proc/self/exe", ec);
  return "cd " + shell_quote(fs::weakly_canonical(fs::absolute(manifest.root)).string()) + " && " +
         shell_quote(ec ? "tracer" : binary.string()) + " golden update --filter " + shell_quote("^" + name + "$");
}

namespace {

// The file that marks a directory as a golden report this tracer made: --reset removes only a
// directory holding it, so a mistyped --report can never delete the user's files.
constexpr const char* kReportMarker = ".tracer-golden-report";

void make_report_dir(const fs::path& dir) {
  fs::create_directories(dir / "rows");
  write_file_atomically((dir / kReportMarker).string(), "a golden report written by tracer (docs/golden.md)\n");
}

// Every command that writes into a report directory it does not find makes it a marked one.
void ensure_report_dir(const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(dir, ec))) make_report_dir(dir);
}

}  // namespace

void prepare_report_dir(const std::string& report_dir) {
  const fs::path dir(report_dir);
  try {
    ensure_report_dir(dir);
    fs::create_directories(dir / "rows");
  } catch (const fs::filesystem_error& e) {
    throw InputError(report_dir + ": --report: cannot make the report directory: " + e.code().message());
  }
}

void write_report_row(const std::string& report_dir, const GoldenManifest& manifest, const GoldenEntry& entry,
                      const GoldenRender* render, const GoldenOutcome& outcome) {
  const fs::path dir(report_dir);
  ensure_report_dir(dir);
  fs::create_directories(dir / "rows");
  Json row;
  row["name"] = entry.name;
  row["status"] = status_name(outcome.status);
  row["message"] = outcome.message;
  row["scene"] = entry.scene;
  row["options"] = options_summary(entry.options);
  row["seconds"] = render ? render->seconds : 0.0;
  row["nonfinite"] = outcome.nonfinite_values;
  row["update"] = update_command(manifest, entry.name);
  row["images"] = Json::object();
  row["amplification"] = 0.0;
  row["metrics"] = nullptr;
  if (outcome.metrics && outcome.metrics->same_size) {
    const CompareResult& m = *outcome.metrics;
    row["metrics"] = {{"pixels", m.pixels},       {"not_identical", m.pixels_not_identical},
                      {"max_error", m.max_error}, {"max_x", m.max_x},
                      {"max_y", m.max_y},         {"mean_error", m.mean_error},
                      {"rms_error", m.rms_error}, {"psnr", m.psnr}};
  }
  if (outcome.status == GoldenStatus::Fail || outcome.status == GoldenStatus::Error) {
    const fs::path images = dir / entry.name;
    fs::create_directories(images);
    if (render) {
      write_image(render->image, (images / "new.exr").string());
      write_image(render->image, (images / "new.png").string());
      row["images"]["new"] = entry.name + "/new.png";
      row["images"]["new_exr"] = entry.name + "/new.exr";
    }
    if (outcome.reference) {
      write_image(*outcome.reference, (images / "reference.png").string());
      row["images"]["reference"] = entry.name + "/reference.png";
    }
    if (render && outcome.reference && outcome.metrics && outcome.metrics->same_size) {
      Image diff;
      row["amplification"] = amplified_difference(render->image, *outcome.reference, diff);
      write_image(diff, (images / "difference.png").string());
      row["images"]["difference"] = entry.name + "/difference.png";
    }
  }
  write_file_atomically((dir / "rows" / (entry.name + ".json")).string(), row.dump(2) + "\n");
}

void reset_report(const std::string& report_dir) {
  const fs::path dir(report_dir);
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(dir, ec);
  if (!fs::exists(status)) return make_report_dir(dir);
  const std::string refusal = report_dir + ": not removed: ";
  if (fs::is_symlink(status)) throw InputError(refusal + "a symbolic link, not a report directory this tracer made");
  if (!fs::is_directory(status)) throw InputError(refusal + "not a directory");
  if (fs::is_empty(dir, ec)) return make_report_dir(dir);
  if (!fs::is_regular_file(fs::symlink_status(dir / kReportMarker, ec)))
    throw InputError(refusal + "it holds files but no " + kReportMarker +
                     ", so it is not a golden report this tracer made (remove it yourself or name another --report)");
  fs::remove_all(dir, ec);
  if (ec) throw InputError(report_dir + ": cannot clear the golden report: " + ec.message());
  make_report_dir(dir);
}

ReportCounts assemble_report(const std::string& report_dir) {
  const fs::path dir(report_dir);
  struct Row {
    Json json;
    std::string html;  // made once, when the row is read: making it is what checks its keys
  };
  std::vector<Row> rows;
  if (fs::is_directory(dir / "rows"))
    for (const auto& file : fs::directory_iterator(dir / "rows")) {
      if (file.path().extension() != ".json") continue;
      const std::string path = file.path().string();
      Json row = parse_json_text(read_text_file(path, "report row"), path);
      std::string html;
      // A row golden check did not write as it writes them (edited, cut short) is refused naming
      // the file and what is wrong, not with the JSON library's exception.
      try {
        static const std::set<std::string> kStatuses = {"error", "fail", "skipped", "pass"};
        if (!kStatuses.count(row.at("status").get<std::string>()))
          throw InputError(path + ": status: expected error, fail, skipped or pass");
        for (const char* key : {"name", "scene", "options", "message"})
          if (!row.at(key).is_string())
            throw InputError(path + ": " + key + ": expected a string (a report row as golden check writes it)");
        html = row_html(row);
      } catch (const Json::exception& e) {
        std::string what = e.what();  // "[json.exception.out_of_range.403] key 'scene' not found"
        if (what.rfind("[json.exception", 0) == 0 && what.find("] ") != std::string::npos)
          what = what.substr(what.find("] ") + 2);
        throw InputError(path + ": not a report row as golden check writes it: " + what);
      }
      rows.push_back({std::move(row), std::move(html)});
    }
  // Failing rows first (errors, then differences), then skipped, then passes; by name within each.
  const auto rank = [](const Row& r) {
    const std::string s = r.json["status"].get<std::string>();
    return s == "error" ? 0 : s == "fail" ? 1 : s == "skipped" ? 2 : 3;
  };
  std::sort(rows.begin(), rows.end(), [&](const Row& a, const Row& b) {
    return std::pair(rank(a), a.json["name"].get<std::string>()) <
           std::pair(rank(b), b.json["name"].get<std::string>());
  });
  ReportCounts counts;
  std::string body;
  for (const Row& r : rows) {
    const int k = rank(r);
    (k == 0 ? counts.errors : k == 1 ? counts.failed : k == 2 ? counts.skipped : counts.passed) += 1;
    body += r.html;
  }
  std::ostringstream html;
  html << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>tracer golden report</title><style>"
       << kStyle << "</style></head>\n<body data-broken-images=\"unknown\">\n<h1>Golden images: " << counts.failed
       << " differ, " << counts.errors << " could not be checked, " << counts.skipped << " skipped, " << counts.passed
       << " identical</h1>\n"
       << "<p id=\"broken\" hidden></p>\n"
       << (rows.empty() ? "<p>No golden was checked in this run.</p>\n" : "") << "<table class=\"report\"><tbody>\n"
       << body << "</tbody></table>\n"
       << kScript << "\n</body></html>\n";
  ensure_report_dir(dir);
  write_file_atomically((dir / "index.html").string(), html.str());
  return counts;
}

}  // namespace tracer
