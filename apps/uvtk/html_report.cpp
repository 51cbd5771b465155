#include "html_report.h"

#include <cstdio>
#include <sstream>

#include "io/image_io.h"

namespace uvtk::cli {

namespace {

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

// A JSON leaf as table text.
std::string cell(const nlohmann::json& value) {
  if (value.is_number_float()) return number(value.get<double>());
  if (value.is_string()) return escaped(value.get<std::string>());
  if (value.is_array() && value.size() > 8) return std::to_string(value.size()) + " entries (see the JSON report)";
  return escaped(value.dump());
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
      << escaped(title) << "\">";
  for (int i = 0; i < bars && highest > 0.0; ++i) {
    const double barHeight = height * fractions[std::size_t(i)] / highest;
    svg << "<rect x=\"" << number(double(width) * i / bars) << "\" y=\"" << number(height - barHeight) << "\" width=\""
        << number(double(width) / bars - 1.0) << "\" height=\"" << number(barHeight) << "\" fill=\"#4a7ab8\"><title>["
        << number(edges[std::size_t(i)]) << ", " << number(edges[std::size_t(i) + 1])
        << "): " << number(100.0 * fractions[std::size_t(i)]) << "% of the area</title></rect>";
  }
  svg << "<text x=\"0\" y=\"" << height + 15 << "\" font-size=\"11\">" << number(edges.front()) << "</text>"
      << "<text x=\"" << width << "\" y=\"" << height + 15 << "\" font-size=\"11\" text-anchor=\"end\">"
      << number(edges.back()) << "</text></svg><figcaption>" << escaped(title) << " ("
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
      html << "<tr><th>" << escaped(prefix + key) << "</th><td>" << cell(value) << "</td></tr>\n";
    }
  }
}

}  // namespace

std::string htmlReport(const nlohmann::json& report, const std::vector<std::pair<std::string, Image>>& views) {
  const std::string title = "uvtk report: " + report.at("input").at("path").get<std::string>();
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << escaped(title) << "</title>\n"
       << "<style>body{font-family:sans-serif;margin:2em;max-width:80em}table{border-collapse:collapse}"
          "th,td{border:1px solid #ccc;padding:2px 8px;text-align:left}td{font-family:monospace}"
          "figure{display:inline-block;margin:0 1em 1em 0;vertical-align:top}</style></head><body>\n"
       << "<h1>" << escaped(title) << "</h1>\n";
  html << "<h2>Views</h2>\n";
  for (const auto& [name, image] : views)
    html << "<figure><img alt=\"" << escaped(name) << " view\" src=\"" << io::pngDataUri(image) << "\" width=\""
         << image.width << "\" height=\"" << image.height << "\"><figcaption>" << escaped(name)
         << "</figcaption></figure>\n";
  html << "<h2>Histograms</h2>\n";
  for (const char* key : {"stretch_l2_faces", "stretch_linf_faces", "angle", "area"})
    html << histogramSvg(key, report.at(key)) << "\n";
  html << "<h2>Measures</h2>\n<table>\n";
  tableRows(html, report, "");
  html << "</table>\n<p>Measures: docs/conventions.md section 8 (Sander et al. 2001 stretch; area-weighted "
          "statistics over the faces of status ok).</p>\n</body></html>\n";
  return html.str();
}

}  // namespace uvtk::cli
