#include "inspect/verdict.h"

namespace uvtk::inspect {

std::string verdictLine(const analysis::Judgement& j) {
  const std::string verdict = std::string("verdict ") + analysis::toString(j.verdict);
  return j.reasons.empty() ? verdict : verdict + ": " + j.reasonsText();
}

}  // namespace uvtk::inspect
