// Text inside HTML and SVG pages.
#pragma once

#include <string>

namespace uvtk {

// `text` with & < > " ' as entities: safe in XML and HTML text and in quoted attributes.
std::string xmlEscaped(const std::string& text);

}  // namespace uvtk
