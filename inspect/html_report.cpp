#include "inspect/html_report.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>

#include "core/error.h"
#include "core/markup.h"
#include "inspect/html_page.h"
#include "inspect/mesh_view.h"
#include "io/image_io.h"
#include "io/json_text.h"

namespace uvtk::inspect {

namespace {

std::string cell(const nlohmann::json& value);

// An array of records (the verdict's reasons, the texels' levels) as a table: a column per key, in
// the order the keys first appear.
std::string recordsTable(const nlohmann::json& records) {
  std::vector<std::string> keys;
  for (const nlohmann::json& r : records)
    for (const auto& [key, value] : r.items())
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
  std::string html = "<table class=\"records\"><tr>";
  for (const std::string& key : keys) html += "<th>" + xmlEscaped(key) + "</th>";
  html += "</tr>";
  for (const nlohmann::json& r : records) {
    html += "<tr>";
    for (const std::string& key : keys) html += "<td>" + (r.contains(key) ? cell(r.at(key)) : std::string()) + "</td>";
    html += "</tr>";
  }
  return html + "</table>";
}

// A JSON value as table text.
std::string cell(const nlohmann::json& value) {
  if (value.is_null()) return "—";  // not measured
  if (value.is_number_float()) return number(value.get<double>());
  if (value.is_string()) return xmlEscaped(value.get<std::string>());
  if (value.is_array() && !value.empty() && value.front().is_object()) return recordsTable(value);
  if (value.is_array() && value.size() > 8) return std::to_string(value.size()) + " entries (see the JSON report)";
  return xmlEscaped(io::jsonText(value));
}

// An overlap fraction as the pages show it: a percentage of the covered UV area.
std::string overlapPercent(const nlohmann::json& fraction) {
  return fraction.is_null() ? cell(fraction) : number(100.0 * fraction.get<double>()) + " %";
}

// A verdict's reasons as badges and their texts, one per line (the gallery's rows and pictures).
std::string reasonLines(const nlohmann::json& reasons) {
  std::string html;
  for (const nlohmann::json& r : reasons)
    html += "<br>" + verdictBadge(r.at("severity").get<std::string>()) + " " + xmlEscaped(r.at("text").get<std::string>());
  return html;
}

// A bar chart of a histogram record of statisticsJson: bar heights are the weight fractions.
std::string histogramSvg(const std::string& title, const nlohmann::json& statistics) {
  const nlohmann::json& h = statistics.at("histogram");
  const std::vector<double> fractions = h.at("weight_fraction").get<std::vector<double>>();
  const std::vector<double> edges = h.at("edges").get<std::vector<double>>();
  const int width = 320, height = 120, bars = int(fractions.size());
  double highest = 0.0;
  for (double f : fractions) highest = std::max(highest, f);
  std::ostringstream svg;
  svg << "<figure><svg width=\"" << width << "\" height=\"" << height + 20 << "\" role=\"img\" aria-label=\""
      << xmlEscaped(title) << "\">";
  for (int i = 0; i < bars && highest > 0.0; ++i) {
    const double barHeight = height * fractions[std::size_t(i)] / highest;
    svg << "<rect x=\"" << number(double(width) * i / bars) << "\" y=\"" << number(height - barHeight) << "\" width=\""
        << number(double(width) / bars - 1.0) << "\" height=\"" << number(barHeight) << "\" fill=\"#4a7ab8\"><title>["
        << number(edges[std::size_t(i)]) << ", " << number(edges[std::size_t(i) + 1])
        << "): " << number(100.0 * fractions[std::size_t(i)]) << "% of the area</title></rect>";
  }
  svg << "<text x=\"0\" y=\"" << height + 15 << "\" font-size=\"11\">" << number(edges.front()) << "</text>"
      << "<text x=\"" << width << "\" y=\"" << height + 15 << "\" font-size=\"11\" text-anchor=\"end\">"
      << number(edges.back()) << "</text></svg><figcaption>" << xmlEscaped(title) << " ("
      << h.at("spacing").get<std::string>() << " bins, bar height: fraction of the surface area)</figcaption></figure>";
  return svg.str();
}

// Rows "key | value" for every leaf of `object`, nested keys joined with '.'.
void tableRows(std::ostringstream& html, const nlohmann::json& object, const std::string& prefix) {
  for (const auto& [key, value] : object.items()) {
    if (key == "histogram") continue;
    if (value.is_object()) {
      tableRows(html, value, prefix + key + ".");
    } else {
      html << "<tr><th>" << xmlEscaped(prefix + key) << "</th><td class=\"num\">" << cell(value) << "</td></tr>\n";
    }
  }
}

// Every measure of the report, one collapsible table per group: its top-level values, then each
// record ("stretch_l2_faces", "seams", "mapping"...) with its leaves.
std::string measureGroups(const nlohmann::json& report) {
  std::ostringstream html;
  html << "<details open><summary>mesh</summary><table>\n";
  for (const auto& [key, value] : report.items())
    if (!value.is_object()) html << "<tr><th>" << xmlEscaped(key) << "</th><td class=\"num\">" << cell(value) << "</td></tr>\n";
  html << "</table></details>\n";
  for (const auto& [key, value] : report.items())
    if (value.is_object()) {
      html << "<details><summary>" << xmlEscaped(key) << "</summary><table>\n";
      tableRows(html, value, "");
      html << "</table></details>\n";
    }
  return html.str();
}

// The measures a reader checks first, each with what it means (docs/conventions.md section 8).
std::string keyMeasures(const nlohmann::json& report) {
  struct Row {
    std::string name, value, meaning;
  };
  const auto three = [&](const char* key) {
    const nlohmann::json& s = report.at(key);
    return cell(s.at("mean")) + " / " + cell(s.at("p99")) + " / " + cell(s.at("max"));
  };
  const nlohmann::json& counts = report.at("status_counts");
  const nlohmann::json& seams = report.at("seams");
  const std::vector<Row> rows{
      {"L2 stretch, whole mesh", cell(report.at("stretch_l2")),
       "Sander's root-mean-square stretch, normalised: 1 is isometric (no texel stretched); the root of the mean "
       "square of the per-face values, so above their mean, far above where a few faces stretch a lot"},
      {"L2 stretch per face: mean / p99 / max", three("stretch_l2_faces"), "the same per face, area-weighted over ok faces"},
      {"L∞ stretch per face: mean / p99 / max", three("stretch_linf_faces"), "the largest stretch in any direction"},
      {"angle distortion σ₁/σ₂: mean / p99 / max", three("angle"), "1 is conformal (angles kept)"},
      {"area distortion log₂ r: mean / p99 / max", three("area"), "0 is equiareal; +1: twice the texels per area, -1: half"},
      {"flipped faces", cell(counts.at("flipped")), "UV triangles mirrored against the majority's winding"},
      {"invalid faces", cell(counts.at("invalid")), "a corner without a valid UV (a missed ray, not finite, no vt)"},
      {"pole faces", cell(counts.at("pole_face")), "faces at a projector's pole, where u is undefined"},
      {"seams: wrap / cut edges", cell(seams.at("wrap_edges")) + " / " + cell(seams.at("cut_edges")),
       "edges whose faces' UVs differ: by a whole turn (wrap) or otherwise (cut)"},
      {"overlap", overlapPercent(report.at("overlap_fraction")),
       "share of the covered UV pixels that more than one face covers"}};
  std::ostringstream html;
  html << "<table class=\"key-measures\">\n<tr><th>measure</th><th>value</th><th>meaning</th></tr>\n";
  for (const Row& r : rows)
    html << "<tr><th>" << xmlEscaped(r.name) << "</th><td class=\"num\">" << r.value << "</td><td>" << xmlEscaped(r.meaning)
         << "</td></tr>\n";
  html << "</table>\n";
  return html.str();
}

}  // namespace

namespace {

// The files of the gallery's page: their links relative to the page, and only those that exist.
class PageFiles {
 public:
  explicit PageFiles(const std::string& pagePath) {
    std::error_code error;
    folder_ = std::filesystem::weakly_canonical(std::filesystem::absolute(pagePath, error), error).parent_path();
    if (error) throw OutputError(pagePath + ": error: cannot write: " + error.message());
  }
  std::optional<std::string> link(const std::string& file) const {
    std::error_code error;
    const std::filesystem::path target = std::filesystem::weakly_canonical(std::filesystem::absolute(file), error);
    if (error || !std::filesystem::is_regular_file(target, error)) return std::nullopt;
    return target.lexically_relative(folder_).generic_string();
  }
  // Links to those of `files` that exist.
  std::string links(const nlohmann::json& files) const {
    std::string html;
    for (const nlohmann::json& file : files)
      if (const std::optional<std::string> href = link(file.get<std::string>()))
        html += "<a href=\"" + xmlEscaped(*href) + "\">" + xmlEscaped(*href) + "</a> ";
    return html;
  }

 private:
  std::filesystem::path folder_;
};

// The verdict and every reason, as a list.
std::string verdictSection(const nlohmann::json& report) {
  std::ostringstream html;
  html << "<section id=\"verdict\"><h2>Verdict " << verdictBadge(report.at("verdict").get<std::string>()) << "</h2>\n";
  const nlohmann::json& reasons = report.at("reasons");
  if (reasons.empty()) {
    html << "<p>No rule triggered (docs/conventions.md section 11 lists the rules and thresholds).</p>\n";
  } else {
    html << "<table class=\"reasons\">\n<tr><th>severity</th><th>rule</th><th>value</th><th>threshold</th>"
            "<th>faces</th><th>what to do</th></tr>\n";
    for (const nlohmann::json& r : reasons)
      html << "<tr><td>" << verdictBadge(r.at("severity").get<std::string>()) << "</td><td>" << cell(r.at("code"))
           << "</td><td class=\"num\">" << cell(r.at("value")) << "</td><td class=\"num\">" << cell(r.at("threshold"))
           << "</td><td class=\"num\">" << cell(r.at("faces")) << "</td><td>" << cell(r.value("advice", nlohmann::json()))
           << "</td></tr>\n";
    html << "</table>\n";
  }
  html << "</section>\n";
  return html.str();
}

bool isPicture(const std::string& file) {
  const std::string extension = std::filesystem::path(file).extension().string();
  return extension == ".png" || extension == ".jpg" || extension == ".jpeg";
}

}  // namespace

std::string galleryHtml(const nlohmann::json& run, const std::string& pagePath,
                        const std::vector<std::pair<std::string, std::string>>& views3d) {
  const PageFiles files(pagePath);
  std::ostringstream html;
  html << pageStart(run.at("title").get<std::string>());
  html << "<p>Scene <code>" << xmlEscaped(run.at("scene").get<std::string>()) << "</code>, written by uvtk "
       << UVTK_VERSION << " (<code>uvtk run</code>).</p>\n";
  if (!run.at("failures").empty()) {
    html << "<h2 class=\"failed\">Failures</h2>\n<ul>\n";
    for (const nlohmann::json& failure : run.at("failures"))
      html << "<li class=\"failed\">" << xmlEscaped(failure.at("message").get<std::string>()) << "</li>\n";
    html << "</ul>\n";
  }
  const nlohmann::json& outputs = run.at("outputs");
  const auto kind = [](const nlohmann::json& o) { return o.at("kind").get<std::string>(); };
  // Each mapping's report page, where it has one: its verdict badges open it.
  std::map<std::string, std::string> reportPages;
  for (const nlohmann::json& o : outputs)
    if (kind(o) == "report" && o.contains("mapping"))
      for (const nlohmann::json& file : o.at("files"))
        if (std::filesystem::path(file.get<std::string>()).extension() == ".html")
          if (const std::optional<std::string> href = files.link(file.get<std::string>()))
            reportPages.emplace(o.at("mapping").get<std::string>(), *href);
  // A report output's own page, else its own JSON; another output's, its mapping's report page.
  const auto reportLink = [&](const nlohmann::json& o) -> std::optional<std::string> {
    if (kind(o) == "report") {
      std::optional<std::string> json;
      for (const nlohmann::json& file : o.at("files")) {
        const std::optional<std::string> href = files.link(file.get<std::string>());
        if (href && std::filesystem::path(*href).extension() == ".html") return href;
        if (href && !json) json = href;
      }
      if (json) return json;
    }
    const auto page = reportPages.find(o.value("mapping", std::string()));
    if (page == reportPages.end()) return std::nullopt;
    return page->second;
  };
  const auto badge = [&](const nlohmann::json& o) {
    const std::string b = verdictBadge(o.at("verdict").get<std::string>());
    const std::optional<std::string> href = reportLink(o);
    return href ? "<a href=\"" + xmlEscaped(*href) + "\" title=\"open the report\">" + b + "</a>" : b;
  };

  html << "<h2>Mappings</h2>\n<table>\n<tr><th>mesh</th><th>mapping</th><th>verdict (opens the report)</th>"
          "<th>L2 stretch</th><th>Linf stretch</th><th>angle (mean)</th><th>seam length</th><th>overlap</th>"
          "<th>files</th></tr>\n";
  for (const nlohmann::json& o : outputs)
    if (kind(o) == "report" && o.contains("stretch_l2"))
      html << "<tr><td>" << cell(o.at("mesh")) << "</td><td>" << cell(o.at("mapping")) << "</td><td>" << badge(o)
           << reasonLines(o.at("reasons")) << "</td><td class=\"num\">" << cell(o.at("stretch_l2"))
           << "</td><td class=\"num\">" << cell(o.at("stretch_linf")) << "</td><td class=\"num\">"
           << cell(o.at("angle_mean")) << "</td><td class=\"num\">" << cell(o.at("seam_length"))
           << "</td><td class=\"num\">" << overlapPercent(o.at("overlap_fraction")) << "</td><td>"
           << files.links(o.at("files")) << "</td></tr>\n";
  html << "</table>\n";

  if (!views3d.empty()) {
    html << "<h2>In 3D</h2>\n";
    for (std::size_t v = 0; v < views3d.size(); ++v)
      html << "<details" << (v == 0 ? " open" : "") << "><summary>" << xmlEscaped(views3d[v].first) << "</summary>\n"
           << views3d[v].second << "</details>\n";
  }

  bool benchTitle = false;
  for (const nlohmann::json& o : outputs)
    if (kind(o) == "bench" && o.contains("svg")) {
      if (!benchTitle) html << "<h2>Speed and accuracy</h2>\n";
      benchTitle = true;
      html << "<figure class=\"chart\">" << o.at("svg").get<std::string>() << "<figcaption>"
           << xmlEscaped(o.value("title", std::string())) << ", mesh " << cell(o.at("mesh")) << " (point at a dot for its "
           << "configuration): " << files.links(o.at("files")) << "</figcaption></figure>\n";
    }

  html << "<h2>Pictures</h2>\n";
  for (const nlohmann::json& o : outputs)
    for (const nlohmann::json& file : o.at("files")) {
      const std::optional<std::string> src = files.link(file.get<std::string>());
      if (!src || !isPicture(*src)) continue;
      std::string caption =
          kind(o) == "compare" ? "ranking of " + o.value("mesh", std::string()) : o.value("mapping", std::string());
      if (o.contains("views")) caption += ": " + io::jsonText(o.at("views"));
      std::string verdict;  // each mapping's picture says how its mapping was judged
      if (o.contains("verdict")) verdict = badge(o) + reasonLines(o.value("reasons", nlohmann::json::array())) + "<br>";
      html << "<figure><a href=\"" << xmlEscaped(*src) << "\"><img alt=\"" << xmlEscaped(caption) << "\" src=\""
           << xmlEscaped(*src) << "\"></a><figcaption>" << verdict << xmlEscaped(caption) << "<br><code>" << xmlEscaped(*src)
           << "</code></figcaption></figure>\n";
    }

  html << "<h2>Rankings</h2>\n";
  for (const nlohmann::json& o : outputs)
    if (kind(o) == "compare" && o.contains("top")) {
      html << "<h3>" << cell(o.at("mesh")) << "</h3>\n<p>" << files.links(o.at("files"))
           << "</p>\n<table>\n<tr><th>rank</th><th>mapping</th><th>verdict</th><th>L2 stretch</th><th>why</th></tr>\n";
      for (const nlohmann::json& r : o.at("top"))
        html << "<tr><td>" << cell(r.at("rank")) << "</td><td>" << cell(r.at("name")) << "</td><td>"
             << verdictBadge(r.at("verdict").get<std::string>()) << "</td><td class=\"num\">" << cell(r.at("stretch_l2"))
             << "</td><td>" << cell(r.at("first_reason")) << "</td></tr>\n";
      html << "</table>\n";
    }

  html << "<h2>Meshes with UVs</h2>\n<table>\n<tr><th>mapping</th><th>verdict</th><th>seam edges</th><th>pole faces</th>"
          "<th>invalid vertices</th><th>files</th></tr>\n";
  for (const nlohmann::json& o : outputs)
    if ((kind(o) == "obj" || kind(o) == "mesh") && o.contains("summary")) {
      const nlohmann::json& summary = o.at("summary");
      const nlohmann::json& seams = summary.at("judgement").at("seams");
      html << "<tr><td>" << cell(o.value("mapping", nlohmann::json())) << "</td><td>" << badge(o)
           << reasonLines(o.at("reasons")) << "</td><td class=\"num\">"
           << cell(seams.at("wrap_edges").get<std::size_t>() + seams.at("cut_edges").get<std::size_t>())
           << "</td><td class=\"num\">" << cell(summary.value("pole_faces", nlohmann::json())) << "</td><td class=\"num\">"
           << cell(summary.value("invalid_vertices", nlohmann::json())) << "</td><td>" << files.links(o.at("files"))
           << "</td></tr>\n";
    }
  html << "</table>\n";

  html << "<h2>Stages</h2>\n<p>Only what the outputs need was computed.</p>\n<table>\n<tr><th>stage</th>"
          "<th>subject</th><th>computes</th><th>ms</th><th>status</th></tr>\n";
  for (const nlohmann::json& stage : run.at("stages"))
    html << "<tr><td>" << cell(stage.at("stage")) << "</td><td>" << cell(stage.at("subject")) << "</td><td>"
         << cell(stage.at("computes")) << "</td><td class=\"num\">" << cell(stage.value("milliseconds", nlohmann::json()))
         << "</td><td>" << cell(stage.at("status")) << "</td></tr>\n";
  html << "</table>\n";
  if (!views3d.empty()) html << meshViewScripts();
  html << "</body></html>\n";
  return html.str();
}

std::string htmlReport(const nlohmann::json& report, const std::vector<std::pair<std::string, Image>>& views,
                       const std::string& view3d) {
  // A mesh the library or Python made in memory has no path: "a mesh in memory".
  const std::string title =
      "uvtk report: " + report.value("input", nlohmann::json::object()).value("path", std::string("a mesh in memory"));
  std::ostringstream html;
  html << pageStart(title);
  html << "<style>.first-screen{display:flex;flex-wrap:wrap;gap:1.5em;align-items:flex-start}"
          ".first-screen .view3d{flex:1 1 32em;max-width:46em}.first-screen .key-measures{flex:1 1 28em}"
          ".key-measures td:last-child{color:#555;font-size:.9em}</style>\n";
  html << verdictSection(report);
  html << "<div class=\"first-screen\">\n" << view3d << keyMeasures(report) << "</div>\n";
  html << "<h2>All measures</h2>\n" << measureGroups(report)
       << "<p>Measures: docs/conventions.md section 8 (Sander et al. 2001 stretch; area-weighted statistics over the "
          "faces of status ok).</p>\n";
  html << "<h2>Views</h2>\n";
  for (const auto& [name, image] : views)
    html << "<figure><img alt=\"" << xmlEscaped(name) << " view\" src=\"" << io::pngDataUri(image) << "\" width=\""
         << image.width << "\" height=\"" << image.height << "\"><figcaption>" << xmlEscaped(name)
         << "</figcaption></figure>\n";
  html << "<h2>Histograms</h2>\n";
  for (const char* key : {"stretch_l2_faces", "stretch_linf_faces", "angle", "area"})
    html << histogramSvg(key, report.at(key)) << "\n";
  if (!view3d.empty()) html << meshViewScripts();
  html << "</body></html>\n";
  return html.str();
}

}  // namespace uvtk::inspect
