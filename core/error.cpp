#include "core/error.h"

#include <cstdio>
#include <cstdlib>

namespace uvtk {

void checkFailed(const char* expression, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: internal error: check failed: %s\n", file, line, expression);
  std::abort();
}

}  // namespace uvtk
