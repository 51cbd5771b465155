// What every uvtk page shares: numbers as the pages print them, the page's head and style, and the
// verdict badge. Text goes in through xmlEscaped (core/markup.h).
#pragma once

#include <string>

namespace uvtk::inspect {

// "%.6g".
std::string number(double value);

// <!DOCTYPE html> through the <h1> of `title`, with the pages' style sheet.
std::string pageStart(const std::string& title);

// A verdict badge ("pass", "warn", "fail"), coloured: <span class="verdict pass">.
std::string verdictBadge(const std::string& verdict);

}  // namespace uvtk::inspect
