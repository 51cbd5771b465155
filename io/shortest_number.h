// The shortest decimal text of a double that reads back as the same double, as the mesh writers
// put it in OBJ and ASCII PLY files.
#pragma once

namespace uvtk::io {

// The longest text writeShortest writes: "-1.2345678901234567e-308".
constexpr int kShortestNumberBytes = 24;

// Writes at `out` exactly what std::to_chars(out, out + 32, value) writes (plain format: fixed
// or scientific, whichever is shorter, fixed on a tie; "-0", "inf", "nan"), and returns its end.
// Dragonbox finds the digits and this function places them, in a quarter to a third less time than
// libstdc++'s Ryu for the 17-digit coordinates of a mesh; the few values whose fixed text needs more
// than their shortest digits (whole numbers beyond 2^50) are left to std::to_chars.
char* writeShortest(char* out, double value);

}  // namespace uvtk::io
