// Stage times as every report gives them: milliseconds on the steady clock.
#pragma once

#include <chrono>

namespace uvtk {

inline double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace uvtk
