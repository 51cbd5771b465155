// The verdict of a judgement as one line of text (docs/conventions.md §11).
#pragma once

#include <string>

#include "analysis/judgement.h"

namespace uvtk::inspect {

// "verdict fail: flipped_area 0.5 > 0.001 (1152 faces); overlap 1 > 0.01 (2304 faces)"
std::string verdictLine(const analysis::Judgement& judgement);

}  // namespace uvtk::inspect
