// The arithmetic a mapping is evaluated in: the speed-accuracy choices a user makes
// (`--precision`, `--math`). docs/precision.md states what each costs and gains.
#pragma once

namespace uvtk {

enum class Precision {
  Double,  // IEEE binary64 throughout
  Float,   // binary32 after the move to the projector's local frame (which is done in double)
};

enum class MathMode {
  Exact,    // libm (glibc): atan2 and friends within 1 ulp, one value at a time
  Fast,     // SLEEF's vectorised 3.5-ULP functions, 4 to 16 values per instruction
  FastU10,  // SLEEF's vectorised 1.0-ULP functions
};

struct Arithmetic {
  Precision precision = Precision::Double;
  MathMode math = MathMode::Exact;
};

}  // namespace uvtk
