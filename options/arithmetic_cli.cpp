#include "options/arithmetic_cli.h"

#include "options/cli_values.h"

namespace uvtk::cli {

void addArithmeticOptions(CLI::App& app, Arithmetic& arithmetic, bool withMath) {
  addChoice<Precision>(app, "--precision", arithmetic.precision, param::kPrecisionNames,
                       "Arithmetic of the per-vertex evaluation: double, or float after the move to the local frame")
      ->default_str("double");
  if (withMath)
    addChoice<MathMode>(app, "--math", arithmetic.math, param::kMathNames,
                        "atan2 from libm (exact), or SLEEF's vectorised functions within 3.5 ULP (fast) or 1.0 ULP "
                        "(fast-u10)")
        ->default_str("exact");
}

nlohmann::json arithmeticJson(const Arithmetic& arithmetic) {
  return {{"precision", param::precisionName(arithmetic.precision)}, {"math", param::mathName(arithmetic.math)}};
}

}  // namespace uvtk::cli
