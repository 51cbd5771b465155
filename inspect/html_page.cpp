#include "inspect/html_page.h"

#include <cstdio>

#include "core/markup.h"

namespace uvtk::inspect {

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

namespace {

constexpr const char* kStyle =
    "<style>body{font-family:'DejaVu Sans',sans-serif;margin:1.5em 2em;max-width:84em;color:#222}"
    "h1{font-size:1.4em;margin:0 0 .4em}h2{font-size:1.15em;margin:1.2em 0 .4em}"
    "table{border-collapse:collapse}th,td{border:1px solid #ccc;padding:2px 8px;text-align:left;vertical-align:top}"
    "td.num{font-family:monospace}figure{display:inline-block;margin:0 1em 1em 0;vertical-align:top}img{max-width:36em}"
    ".failed{color:#b00}.verdict{display:inline-block;padding:2px 10px;border-radius:4px;color:#fff;"
    "font-weight:bold;text-transform:uppercase}.verdict.pass{background:#2a7d2a}.verdict.warn{background:#b07800}"
    ".verdict.fail{background:#b00}details{margin:.3em 0}summary{cursor:pointer;font-weight:bold}</style>";

}  // namespace

std::string pageStart(const std::string& title) {
  return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"><title>" +
         xmlEscaped(title) + "</title>\n" + kStyle + "</head><body>\n<h1>" + xmlEscaped(title) + "</h1>\n";
}

std::string verdictBadge(const std::string& verdict) {
  return "<span class=\"verdict " + xmlEscaped(verdict) + "\">" + xmlEscaped(verdict) + "</span>";
}

}  // namespace uvtk::inspect
