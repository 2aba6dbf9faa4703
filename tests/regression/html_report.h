#pragma once
// The one page that shows every failing regression test: <build>/regression/report.html, a row
// per scene and backend with reference, render and diff side by side and the figures. ctest runs
// each test in its own process, so every failing test rebuilds the page from all the figures.json
// files present, and a passing test removes its stale folder and rebuilds it too. A file lock
// serialises the rebuilds so that tests running at once (ctest -j) never drop each other's rows:
// each writes its figures.json before taking the lock, so the last to take it sees them all.
#include "failure_folder.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace rtpro::regression {

inline std::string html_escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
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

// Figures are numbers or null (not finite, see finite_or_null).
inline std::string figure_text(const nlohmann::json& value, std::string_view when_null = "&infin;") {
  if (!value.is_number()) return std::string(when_null);
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value.get<double>());
  return text;
}

// A member, or null when it is missing (const operator[] must not be used on a missing key).
inline nlohmann::json field(const nlohmann::json& object, const char* key) {
  return object.is_object() && object.contains(key) ? object.at(key) : nlohmann::json(nullptr);
}

inline std::string integer_text(const nlohmann::json& value) {
  return value.is_number_integer() ? std::to_string(value.get<long long>()) : "?";
}

inline std::string image_cell(const nlohmann::json& figures, const char* image) {
  const nlohmann::json& images = figures.value("images", nlohmann::json::object());
  if (!images.contains(image)) return "<td>(none: the images differ in size)</td>";
  const std::string src = html_escaped(figures.value("folder", "") + "/" + images[image].get<std::string>());
  return "<td><a href=\"" + src + "\"><img src=\"" + src + "\" alt=\"" + image + "\"></a></td>";
}

inline std::string figures_cell(const nlohmann::json& f) {
  const nlohmann::json limits = field(f, "thresholds");
  const nlohmann::json at = field(f, "max_error_at");
  const std::string folder = html_escaped(f.value("folder", ""));
  std::string cell = "<td><table class=\"figures\">";
  const auto row = [&cell](std::string_view name, const std::string& value) {
    cell += "<tr><th>" + std::string(name) + "</th><td>" + value + "</td></tr>";
  };
  row("verdict", "<b>" + html_escaped(f.value("verdict", "")) + "</b>");
  row("failing pixels", integer_text(field(f, "fail_pixels")) + " of " + integer_text(field(f, "pixels")) + " (" +
                            figure_text(field(f, "fail_percent")) + "%; allowed " +
                            figure_text(field(limits, "fail_percent")) + "% over " +
                            figure_text(field(limits, "fail")) + ")");
  row("mean error",
      figure_text(field(f, "mean_error")) + " (limit " + figure_text(field(limits, "max_mean_error"), "none") + ")");
  row("RMS error", figure_text(field(f, "rms_error")));
  row("PSNR", figure_text(field(f, "psnr")) + " dB");
  row("max error", figure_text(field(f, "max_error")) + " at (" + integer_text(field(at, "x")) + ", " +
                       integer_text(field(at, "y")) + ") channel " +
                       html_escaped(field(at, "channel").is_string() ? field(at, "channel").get<std::string>() : ""));
  row("diff white at", figure_text(field(f, "diff_full_scale"), "-"));
  row("files", "<a href=\"" + folder + "/rendered.exr\">rendered.exr</a> <a href=\"" + folder +
                   "/figures.json\">figures.json</a> reference: " + html_escaped(f.value("reference", "")));
  return cell + "</table></td>";
}

// The corpus mosaic (corpus_mosaic_test.cpp), when a run made one: the shapes of the real-world
// models, for a person to look at.
inline std::string mosaic_html(bool has_mosaic) {
  if (!has_mosaic) return "";
  return "<h2>Real-world models</h2>\n<p>Every OBJ, PLY and glTF 2.0 file of Debian's assimp-testmodels that loads, "
         "framed by its bounds (<a href=\"corpus_mosaic.txt\">which tile is which</a>):</p>\n"
         "<a href=\"corpus_mosaic.png\"><img class=\"mosaic\" src=\"corpus_mosaic.png\" alt=\"corpus mosaic\"></a>\n";
}

inline std::string report_html(const std::vector<nlohmann::json>& failures, const std::string& update_command,
                               bool has_mosaic = false) {
  std::string html = R"(<!doctype html>
<html><head><meta charset="utf-8"><title>rtpro regression report</title>
<style>
body { font-family: sans-serif; margin: 1.5em; }
table.cases { border-collapse: collapse; }
table.cases > tbody > tr > td, table.cases > tbody > tr > th {
  border: 1px solid #bbb; padding: 6px; vertical-align: top;
}
img { width: 240px; image-rendering: pixelated; display: block; }
img.mosaic { width: auto; }
table.figures { font-size: 90%; min-width: 360px; }
table.figures th { text-align: left; padding-right: 10px; font-weight: normal; color: #555; }
</style></head><body>
<h1>rtpro regression report</h1>
)";
  if (failures.empty())
    return html + "<p>No failing regression tests.</p>\n" + mosaic_html(has_mosaic) + "</body></html>\n";
  html += "<p>" + std::to_string(failures.size()) +
          " failing (scene, backend) pairs. Images are shown through the default OpenColorIO view. The diff "
          "is black where the images agree, rising through blue and red to white at the error its figures "
          "name (the 99th percentile of the per-pixel error, or the largest error when fewer than 1% of the "
          "pixels differ). If the change is intended, regenerate the references with <code>" +
          html_escaped(update_command) + "</code>.</p>\n";
  html +=
      "<table "
      "class=\"cases\"><tr><th>scene</th><th>reference</th><th>rendered</th><th>diff</th><th>figures</th></tr>\n";
  for (const nlohmann::json& f : failures) {
    html += "<tr><td><b>" + html_escaped(f.value("scene", "")) + "</b><br>" + html_escaped(f.value("backend", "")) +
            "<br><small>rule: " + html_escaped(f.value("rule", "")) + "</small></td>";
    html +=
        image_cell(f, "reference") + image_cell(f, "rendered") + image_cell(f, "diff") + figures_cell(f) + "</tr>\n";
  }
  return html + "</table>\n" + mosaic_html(has_mosaic) + "</body></html>\n";
}

// Every complete failure folder's figures, with "folder" set to its name, ordered by name.
inline std::vector<nlohmann::json> collect_failures(const std::filesystem::path& root) {
  std::vector<nlohmann::json> failures;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(root, error)) {
    const std::filesystem::path figures_file = entry.path() / "figures.json";
    if (!std::filesystem::is_regular_file(figures_file)) continue;
    std::ifstream in(figures_file);
    nlohmann::json figures = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (figures.is_discarded() || !figures.is_object()) continue;
    figures["folder"] = entry.path().filename().string();
    failures.push_back(std::move(figures));
  }
  std::sort(failures.begin(), failures.end(),
            [](const nlohmann::json& a, const nlohmann::json& b) { return a["folder"] < b["folder"]; });
  return failures;
}

class ReportLock {
 public:
  explicit ReportLock(const std::filesystem::path& file)
      : fd_(::open(file.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644)) {
    if (fd_ >= 0) ::flock(fd_, LOCK_EX);
  }
  ~ReportLock() {
    if (fd_ >= 0) ::close(fd_);  // closing releases the lock
  }
  ReportLock(const ReportLock&) = delete;
  ReportLock& operator=(const ReportLock&) = delete;

 private:
  int fd_;
};

// Rebuilds root/report.html from the failure folders under root; returns its path.
inline std::filesystem::path regenerate_report(const std::filesystem::path& root, const std::string& update_command) {
  std::filesystem::create_directories(root);
  const ReportLock lock(root / ".report.lock");
  const std::filesystem::path report = root / "report.html";
  write_text_atomically(
      report, report_html(collect_failures(root), update_command, std::filesystem::exists(root / "corpus_mosaic.png")));
  return report;
}

// For a passing test: its old failure folder is stale. Rebuilds the report only when there was one.
inline void clear_failure(const std::filesystem::path& root, const std::string& folder,
                          const std::string& update_command) {
  if (!std::filesystem::exists(root / folder)) return;
  std::filesystem::remove_all(root / folder);
  regenerate_report(root, update_command);
}

}  // namespace rtpro::regression
